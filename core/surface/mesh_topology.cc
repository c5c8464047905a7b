#include "core/surface/mesh_topology.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>
#include <utility>

namespace avc::surface {
namespace {

struct HalfEdge {
  int from = 0;
  int to = 0;
  int face = 0;
};

// Half-edges whose undirected edge has exactly one face, sorted by (from, to, face).
std::vector<HalfEdge> BoundaryHalfEdges(const geometry::Mesh& mesh) {
  std::vector<std::pair<uint64_t, HalfEdge>> all;
  all.reserve(mesh.faces.size() * 3);
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.faces[f][k];
      const int b = mesh.faces[f][(k + 1) % 3];
      all.push_back({EdgeKey(a, b), HalfEdge{a, b, static_cast<int>(f)}});
    }
  }
  std::sort(all.begin(), all.end(), [](const auto& x, const auto& y) {
    return x.first != y.first ? x.first < y.first : x.second.face < y.second.face;
  });
  std::vector<HalfEdge> boundary;
  for (size_t i = 0; i < all.size();) {
    size_t j = i;
    while (j < all.size() && all[j].first == all[i].first) ++j;
    if (j - i == 1) boundary.push_back(all[i].second);
    i = j;
  }
  std::sort(boundary.begin(), boundary.end(), [](const HalfEdge& x, const HalfEdge& y) {
    return std::tie(x.from, x.to, x.face) < std::tie(y.from, y.to, y.face);
  });
  return boundary;
}

int Find(std::vector<int>& parent, int x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

}  // namespace

double BoundaryLoop::Perimeter(const geometry::Mesh& mesh) const {
  double length = 0.0;
  const size_t n = vertices.size();
  const size_t edges = closed ? n : (n == 0 ? 0 : n - 1);
  for (size_t i = 0; i < edges; ++i) {
    length += (mesh.vertices[vertices[(i + 1) % n]] - mesh.vertices[vertices[i]]).norm();
  }
  return length;
}

std::vector<BoundaryLoop> BoundaryLoops(const geometry::Mesh& mesh) {
  const std::vector<HalfEdge> edges = BoundaryHalfEdges(mesh);
  // Outgoing boundary half-edges of a vertex are a contiguous run of the sorted list.
  std::vector<int> first_out(mesh.vertices.size() + 1, 0);
  for (const HalfEdge& e : edges) ++first_out[e.from + 1];
  std::partial_sum(first_out.begin(), first_out.end(), first_out.begin());
  std::vector<bool> used(edges.size(), false);
  auto next_unused = [&](int vertex) -> int {
    for (int k = first_out[vertex]; k < first_out[vertex + 1]; ++k) {
      if (!used[k]) return k;
    }
    return -1;
  };

  std::vector<BoundaryLoop> loops;
  for (size_t start = 0; start < edges.size(); ++start) {
    if (used[start]) continue;
    BoundaryLoop loop;
    int k = static_cast<int>(start);
    while (true) {
      used[k] = true;
      loop.vertices.push_back(edges[k].from);
      loop.faces.push_back(edges[k].face);
      if (edges[k].to == edges[start].from) break;
      const int next = next_unused(edges[k].to);
      if (next < 0) {
        loop.closed = false;
        loop.vertices.push_back(edges[k].to);
        break;
      }
      k = next;
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

std::vector<bool> BoundaryVertices(const geometry::Mesh& mesh) {
  std::vector<bool> boundary(mesh.vertices.size(), false);
  for (const HalfEdge& e : BoundaryHalfEdges(mesh)) {
    boundary[e.from] = true;
    boundary[e.to] = true;
  }
  return boundary;
}

std::vector<bool> OuterLoops(const geometry::Mesh& mesh, const std::vector<BoundaryLoop>& loops) {
  int component_count = 0;
  const std::vector<int> component = FaceComponents(mesh, &component_count);
  std::vector<int> outer(component_count, -1);
  std::vector<double> perimeter(loops.size(), 0.0);
  for (size_t i = 0; i < loops.size(); ++i) {
    if (!loops[i].closed) continue;
    perimeter[i] = loops[i].Perimeter(mesh);
    int& best = outer[component[loops[i].faces[0]]];
    if (best < 0 || perimeter[i] > perimeter[best]) best = static_cast<int>(i);
  }
  std::vector<bool> is_outer(loops.size(), false);
  for (int i : outer) {
    if (i >= 0) is_outer[i] = true;
  }
  return is_outer;
}

std::vector<std::vector<int>> VertexNeighbours(const geometry::Mesh& mesh) {
  std::vector<std::vector<int>> neighbours(mesh.vertices.size());
  for (const Eigen::Vector3i& t : mesh.faces) {
    for (int k = 0; k < 3; ++k) {
      neighbours[t[k]].push_back(t[(k + 1) % 3]);
      neighbours[t[k]].push_back(t[(k + 2) % 3]);
    }
  }
  for (std::vector<int>& list : neighbours) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return neighbours;
}

std::vector<Eigen::Vector3d> VertexNormals(const geometry::Mesh& mesh) {
  std::vector<Eigen::Vector3d> normals(mesh.vertices.size(), Eigen::Vector3d::Zero());
  for (const Eigen::Vector3i& t : mesh.faces) {
    const Eigen::Vector3d a = mesh.vertices[t[0]].cast<double>();
    const Eigen::Vector3d n =
        (mesh.vertices[t[1]].cast<double>() - a).cross(mesh.vertices[t[2]].cast<double>() - a);
    for (int k = 0; k < 3; ++k) normals[t[k]] += n;
  }
  return normals;
}

std::vector<int> FaceComponents(const geometry::Mesh& mesh, int* count) {
  std::vector<int> parent(mesh.vertices.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (const Eigen::Vector3i& t : mesh.faces) {
    for (int k = 1; k < 3; ++k) {
      const int a = Find(parent, t[0]);
      const int b = Find(parent, t[k]);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  }
  std::vector<int> component_of_root(mesh.vertices.size(), -1);
  std::vector<int> components(mesh.faces.size(), -1);
  int next = 0;
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    const int root = Find(parent, mesh.faces[f][0]);
    if (component_of_root[root] < 0) component_of_root[root] = next++;
    components[f] = component_of_root[root];
  }
  if (count != nullptr) *count = next;
  return components;
}

void KeepFaces(geometry::Mesh& mesh, const std::vector<bool>& keep) {
  size_t out = 0;
  const bool labelled = !mesh.face_labels.empty();
  const bool with_materials = !mesh.face_materials.empty();
  for (size_t f = 0; f < mesh.faces.size(); ++f) {
    if (!keep[f]) continue;
    mesh.faces[out] = mesh.faces[f];
    if (labelled) mesh.face_labels[out] = mesh.face_labels[f];
    if (with_materials) mesh.face_materials[out] = mesh.face_materials[f];
    ++out;
  }
  mesh.faces.resize(out);
  if (labelled) mesh.face_labels.resize(out);
  if (with_materials) mesh.face_materials.resize(out);
}

std::vector<int> RemoveUnusedVertices(geometry::Mesh& mesh) {
  std::vector<int> new_index(mesh.vertices.size(), -1);
  for (const Eigen::Vector3i& t : mesh.faces) {
    for (int k = 0; k < 3; ++k) new_index[t[k]] = 0;
  }
  std::vector<int> old_index;
  for (size_t i = 0; i < new_index.size(); ++i) {
    if (new_index[i] < 0) continue;
    new_index[i] = static_cast<int>(old_index.size());
    old_index.push_back(static_cast<int>(i));
  }
  auto compact = [&](auto& attribute) {
    if (attribute.empty()) return;
    for (size_t i = 0; i < old_index.size(); ++i) attribute[i] = attribute[old_index[i]];
    attribute.resize(old_index.size());
  };
  compact(mesh.vertices);
  compact(mesh.colors);
  compact(mesh.uvs);
  for (Eigen::Vector3i& t : mesh.faces) {
    for (int k = 0; k < 3; ++k) t[k] = new_index[t[k]];
  }
  return old_index;
}

double TriangleQuality(const Eigen::Vector3f& a, const Eigen::Vector3f& b,
                       const Eigen::Vector3f& c) {
  const double area = 0.5 * static_cast<double>((b - a).cross(c - a).norm());
  const double squares =
      static_cast<double>((b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm());
  if (!(squares > 0.0)) return 0.0;
  return 4.0 * std::sqrt(3.0) * area / squares;
}

}  // namespace avc::surface
