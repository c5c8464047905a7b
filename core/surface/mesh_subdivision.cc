#include "core/surface/mesh_subdivision.h"

#include <algorithm>
#include <map>
#include <utility>

namespace avc::surface {
namespace {

template <class T>
void CopyToChildren(std::vector<T>& per_face) {
  if (per_face.empty()) return;
  std::vector<T> children;
  children.reserve(4 * per_face.size());
  for (const T& value : per_face) children.insert(children.end(), 4, value);
  per_face = std::move(children);
}

}  // namespace

size_t SubdivideMidpoints(geometry::Mesh& mesh, std::vector<int32_t>* source_points) {
  const size_t old_vertices = mesh.vertices.size();
  const bool colours = mesh.colors.size() == old_vertices;
  const bool uvs = mesh.uvs.size() == old_vertices;
  std::map<std::pair<int, int>, int> midpoint_of_edge;  // ordered: same input, same indices
  const auto midpoint = [&](int a, int b) {
    const std::pair<int, int> key(std::min(a, b), std::max(a, b));
    const auto [it, inserted] =
        midpoint_of_edge.emplace(key, static_cast<int>(mesh.vertices.size()));
    if (inserted) {
      mesh.vertices.push_back(0.5f * (mesh.vertices[a] + mesh.vertices[b]));
      if (colours) {
        mesh.colors.push_back(
            ((mesh.colors[a].cast<int>() + mesh.colors[b].cast<int>() + Eigen::Vector3i::Ones()) /
             2)
                .cast<uint8_t>());
      }
      if (uvs) mesh.uvs.push_back(0.5f * (mesh.uvs[a] + mesh.uvs[b]));
    }
    return it->second;
  };
  std::vector<Eigen::Vector3i> faces;
  faces.reserve(4 * mesh.faces.size());
  for (const Eigen::Vector3i& t : mesh.faces) {
    const int ab = midpoint(t[0], t[1]);
    const int bc = midpoint(t[1], t[2]);
    const int ca = midpoint(t[2], t[0]);
    faces.emplace_back(t[0], ab, ca);  // same winding as the parent
    faces.emplace_back(ab, t[1], bc);
    faces.emplace_back(ca, bc, t[2]);
    faces.emplace_back(ab, bc, ca);
  }
  mesh.faces = std::move(faces);
  CopyToChildren(mesh.face_labels);
  CopyToChildren(mesh.face_materials);
  const size_t added = mesh.vertices.size() - old_vertices;
  if (source_points != nullptr) source_points->resize(mesh.vertices.size(), -1);
  return added;
}

}  // namespace avc::surface
