#include "core/surface/cell_merging.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <unordered_set>
#include <utility>

#include "core/cluster/connected_components.h"
#include "core/cluster/point_grid.h"
#include "core/surface/delaunay_2d.h"
#include "core/surface/mesh_topology.h"
#include "core/surface/plane_frame.h"

namespace avc::surface {
namespace {

using CellPair = std::pair<int, int>;

// For every pair of cells with boundary vertices within their distance of each other (distance
// between clusters, own_cluster_distance within one): those vertices, plus their neighbours
// along the boundary so the boundary edges at the ends of the gap take part too. Sorted and
// unique per pair.
std::map<CellPair, std::vector<int>> NearBoundaryVertices(const geometry::Mesh& mesh,
                                                          const std::vector<int>& vertex_cell,
                                                          const std::vector<int32_t>& cell_labels,
                                                          double distance,
                                                          double own_cluster_distance) {
  std::vector<int> boundary;
  std::vector<Eigen::Vector3f> positions;
  const std::vector<bool> on_boundary = BoundaryVertices(mesh);
  for (size_t v = 0; v < on_boundary.size(); ++v) {
    if (!on_boundary[v]) continue;
    boundary.push_back(static_cast<int>(v));
    positions.push_back(mesh.vertices[v]);
  }
  std::map<CellPair, std::vector<int>> near;
  if (boundary.empty()) return near;
  std::vector<std::vector<int>> along(mesh.vertices.size());
  for (const BoundaryLoop& loop : BoundaryLoops(mesh)) {
    const size_t n = loop.vertices.size();
    for (size_t i = 0; i < n; ++i) {
      if (i + 1 < n || loop.closed) along[loop.vertices[i]].push_back(loop.vertices[(i + 1) % n]);
      if (i > 0 || loop.closed) along[loop.vertices[i]].push_back(loop.vertices[(i + n - 1) % n]);
    }
  }
  const float reach = static_cast<float>(std::max(distance, own_cluster_distance));
  const cluster::PointGrid grid(positions, reach);
  for (size_t i = 0; i < boundary.size(); ++i) {
    const int a = boundary[i];
    grid.ForEachWithin(positions[i], reach, [&](uint32_t j) {
      const int b = boundary[j];
      const int ca = vertex_cell[a];
      const int cb = vertex_cell[b];
      if (ca >= cb) return;  // each pair once, from its lower cell
      const double limit = cell_labels[ca] == cell_labels[cb] ? own_cluster_distance : distance;
      if ((positions[i] - positions[j]).squaredNorm() > limit * limit) return;
      std::vector<int>& list = near[{ca, cb}];
      for (int v : {a, b}) {
        list.push_back(v);
        for (int w : along[v]) list.push_back(w);
      }
    });
  }
  for (auto& [pair, list] : near) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return near;
}

double OwnClusterDistance(const StitchRule& rule) {
  return rule.own_cluster_distance > 0.0 ? rule.own_cluster_distance : rule.distance;
}

// Unit vertex normals as floats, for the link test.
std::vector<Eigen::Vector3f> UnitVertexNormals(const geometry::Mesh& mesh) {
  std::vector<Eigen::Vector3f> unit;
  unit.reserve(mesh.vertices.size());
  for (const Eigen::Vector3d& n : VertexNormals(mesh)) {
    const double length = n.norm();
    unit.push_back(length > 0.0 ? Eigen::Vector3f((n / length).cast<float>())
                                : Eigen::Vector3f::Zero());
  }
  return unit;
}

class GapStitcher {
 public:
  GapStitcher(geometry::Mesh& mesh, const std::vector<int>& vertex_cell,
              const std::vector<int32_t>& cell_labels, const StitchRule& rule)
      : mesh_(mesh),
        vertex_cell_(vertex_cell),
        cell_labels_(cell_labels),
        distance2_(rule.distance * rule.distance),
        own_cluster_distance2_(OwnClusterDistance(rule) * OwnClusterDistance(rule)),
        min_facing_(std::cos(rule.max_tilt_deg * std::numbers::pi / 180.0)),
        normals_(rule.link_slope >= 0.0f ? UnitVertexNormals(mesh)
                                         : std::vector<Eigen::Vector3f>{}) {
    if (rule.clear_of_other_cells && !mesh_.vertices.empty() && rule.distance > 0.0) {
      clearance_radius_ = static_cast<float>(rule.distance);
      vertex_grid_.emplace(mesh_.vertices, clearance_radius_);
    }
    for (const Eigen::Vector3i& t : mesh_.faces) {
      for (int k = 0; k < 3; ++k) half_edges_.insert(HalfEdgeKey(t[k], t[(k + 1) % 3]));
    }
    link_.normals = rule.link_slope >= 0.0f ? &normals_ : nullptr;
    link_.slope = rule.link_slope;
    link_.mean_slope = rule.link_mean_slope;
    link_.allowance = rule.link_allowance;
  }

  // Triangulates the gap between the vertices (of two or more cells) seen along normal.
  size_t Stitch(const std::vector<int>& vertices, const Eigen::Vector3d& normal) {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (int v : vertices) centre += mesh_.vertices[v].cast<double>();
    centre /= static_cast<double>(vertices.size());
    const Eigen::Vector3d along =
        (mesh_.vertices[vertices.back()] - mesh_.vertices[vertices.front()]).cast<double>();
    const PlaneFrame frame = MakePlaneFrame(centre, normal, along);
    std::vector<Eigen::Vector2d> projected;
    projected.reserve(vertices.size());
    for (int v : vertices) projected.push_back(frame.Project(mesh_.vertices[v]));
    size_t added = 0;
    for (const Eigen::Vector3i& t : Delaunay2d(projected)) {
      const Eigen::Vector3i face(vertices[t[0]], vertices[t[1]], vertices[t[2]]);
      if (!InGap(face, normal)) continue;
      Add(face);
      ++added;
    }
    return added;
  }

 private:
  bool InGap(const Eigen::Vector3i& face, const Eigen::Vector3d& normal) const {
    const int c0 = vertex_cell_[face[0]];
    if (c0 == vertex_cell_[face[1]] && c0 == vertex_cell_[face[2]]) return false;
    for (int k = 0; k < 3; ++k) {
      const int a = face[k];
      const int b = face[(k + 1) % 3];
      if (half_edges_.count(HalfEdgeKey(a, b))) return false;  // would double an edge
      if (vertex_cell_[a] == vertex_cell_[b]) {
        // Within a cell only along a free boundary edge b -> a, so the face lies outside it.
        if (!half_edges_.count(HalfEdgeKey(b, a))) return false;
      } else if (!Bridgeable(a, b)) {
        return false;
      }
    }
    const Eigen::Vector3d p = mesh_.vertices[face[0]].cast<double>();
    const Eigen::Vector3d n = (mesh_.vertices[face[1]].cast<double>() - p)
                                  .cross(mesh_.vertices[face[2]].cast<double>() - p);
    const double length = n.norm();
    if (!(length > 0.0 && n.dot(normal) >= min_facing_ * length)) return false;
    return !vertex_grid_ || NearestCellIsOwn(face);
  }

  // The vertex nearest the face's centroid (within the stitch distance) belongs to one of the
  // face's own cells: a bridge between two cells does not pass over or under a third (at a
  // rosette's centre the gap between two leaf bases lies over the base of a third leaf).
  bool NearestCellIsOwn(const Eigen::Vector3i& face) const {
    const Eigen::Vector3f centroid =
        (mesh_.vertices[face[0]] + mesh_.vertices[face[1]] + mesh_.vertices[face[2]]) / 3.0f;
    float best = std::numeric_limits<float>::max();
    int best_cell = -1;
    vertex_grid_->ForEachWithin(centroid, clearance_radius_, [&](uint32_t j) {
      const float d = (mesh_.vertices[j] - centroid).squaredNorm();
      if (d < best) {
        best = d;
        best_cell = vertex_cell_[j];
      }
    });
    return best_cell < 0 || best_cell == vertex_cell_[face[0]] ||
           best_cell == vertex_cell_[face[1]] || best_cell == vertex_cell_[face[2]];
  }

  // An edge between two cells: within the stitch distance for their clusters, and between
  // clusters also on one local surface.
  bool Bridgeable(int a, int b) const {
    const bool one_cluster = cell_labels_[vertex_cell_[a]] == cell_labels_[vertex_cell_[b]];
    const double limit2 = one_cluster ? own_cluster_distance2_ : distance2_;
    if ((mesh_.vertices[a] - mesh_.vertices[b]).squaredNorm() > limit2) return false;
    return one_cluster ||
           link_.Linked(mesh_.vertices, static_cast<uint32_t>(a), static_cast<uint32_t>(b));
  }

  void Add(const Eigen::Vector3i& face) {
    mesh_.faces.push_back(face);
    for (int k = 0; k < 3; ++k) half_edges_.insert(HalfEdgeKey(face[k], face[(k + 1) % 3]));
    const int c0 = vertex_cell_[face[0]];
    const int c1 = vertex_cell_[face[1]];
    const int c2 = vertex_cell_[face[2]];
    const int majority = (c1 == c2) ? c1 : c0;
    if (!mesh_.face_labels.empty()) mesh_.face_labels.push_back(cell_labels_[majority]);
    if (!mesh_.face_materials.empty()) mesh_.face_materials.push_back(0);
  }

  geometry::Mesh& mesh_;
  const std::vector<int>& vertex_cell_;
  const std::vector<int32_t>& cell_labels_;
  double distance2_;
  double own_cluster_distance2_;
  double min_facing_;
  std::vector<Eigen::Vector3f> normals_;  // per vertex, unit
  cluster::LinkRule link_;
  float clearance_radius_ = 0;                     // m: the stitch distance between clusters
  std::optional<cluster::PointGrid> vertex_grid_;  // over every vertex, when clear_of_other_cells
  std::unordered_set<uint64_t> half_edges_;        // membership only: order never matters
};

}  // namespace

geometry::Mesh JoinCells(const std::vector<Cell>& cells, std::vector<int>* vertex_cell) {
  geometry::Mesh joined;
  vertex_cell->clear();
  for (size_t c = 0; c < cells.size(); ++c) {
    if (cells[c].mesh.faces.empty()) continue;
    joined.Append(cells[c].mesh);
    vertex_cell->resize(joined.vertices.size(), static_cast<int>(c));
  }
  return joined;
}

StitchStats StitchCells(geometry::Mesh& mesh, const std::vector<int>& vertex_cell,
                        const std::vector<Eigen::Vector3d>& cell_normals,
                        const std::vector<int32_t>& cell_labels, const StitchRule& rule) {
  StitchStats stats;
  const std::map<CellPair, std::vector<int>> near =
      NearBoundaryVertices(mesh, vertex_cell, cell_labels, rule.distance, OwnClusterDistance(rule));
  GapStitcher stitcher(mesh, vertex_cell, cell_labels, rule);
  for (const auto& [pair, vertices] : near) {
    ++stats.neighbour_pairs;
    const Eigen::Vector3d mean = cell_normals[pair.first] + cell_normals[pair.second];
    // Cells facing opposite ways (more than ~150 degrees apart) have no common side to join on.
    if (mean.norm() < 0.5 || vertices.size() < 3) continue;
    const size_t added = stitcher.Stitch(vertices, mean.normalized());
    if (added > 0) ++stats.stitched_pairs;
    stats.faces += added;
  }
  return stats;
}

}  // namespace avc::surface
