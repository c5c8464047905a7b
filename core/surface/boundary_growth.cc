#include "core/surface/boundary_growth.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "core/surface/mesh_topology.h"

namespace avc::surface {

double EstimateBoundaryBand(const std::vector<Cell>& cells, double spacing, double scale) {
  double area = 0.0;
  size_t faces = 0;
  double outline = 0.0;
  size_t outline_edges = 0;
  for (const Cell& cell : cells) {
    area += geometry::SurfaceArea(cell.mesh);
    faces += cell.mesh.faces.size();
    const std::vector<BoundaryLoop> loops = BoundaryLoops(cell.mesh);
    const std::vector<bool> outer = OuterLoops(cell.mesh, loops);
    for (size_t i = 0; i < loops.size(); ++i) {
      if (!outer[i]) continue;
      outline += loops[i].Perimeter(cell.mesh);
      outline_edges += loops[i].vertices.size();
    }
  }
  if (faces == 0 || outline_edges == 0 || !(outline > 0.0)) return 0.0;
  const double mean_area = area / static_cast<double>(faces);
  const double mean_edge = outline / static_cast<double>(outline_edges);
  if (!(scale > 0.0)) {
    const double regularity = spacing / std::sqrt(2.0 * mean_area);
    scale = 1.0 + kRandomSamplingExtraBand * std::clamp((1.0 - regularity) / 0.53, 0.0, 1.0);
  }
  return scale * mean_area / mean_edge;
}

GrowthStats GrowOuterBoundary(Cell& cell, double band, const std::function<bool(int)>& is_free) {
  GrowthStats stats;
  geometry::Mesh& mesh = cell.mesh;
  if (!(band > 0.0) || mesh.faces.empty()) return stats;
  const std::vector<BoundaryLoop> loops = BoundaryLoops(mesh);
  const std::vector<bool> outer = OuterLoops(mesh, loops);
  // A vertex on two loops (a pinch) has no single outward direction: it stays.
  std::vector<int> loops_through(mesh.vertices.size(), 0);
  for (const BoundaryLoop& loop : loops) {
    for (int v : loop.vertices) ++loops_through[v];
  }
  const std::vector<Eigen::Vector3d> normals = VertexNormals(mesh);
  auto add_face = [&](int a, int b, int c) {
    mesh.faces.emplace_back(a, b, c);
    mesh.face_labels.push_back(cell.cluster);
    ++stats.faces;
  };
  for (size_t l = 0; l < loops.size(); ++l) {
    const BoundaryLoop& loop = loops[l];
    const size_t n = loop.vertices.size();
    if (!outer[l] || n < 3) continue;
    // grown[i]: the new vertex of loop.vertices[i], or -1.
    std::vector<int> grown(n, -1);
    for (size_t i = 0; i < n; ++i) {
      const int v = loop.vertices[i];
      if (loops_through[v] != 1 || !is_free(v)) continue;
      const Eigen::Vector3d p = mesh.vertices[v].cast<double>();
      const Eigen::Vector3d tangent = (mesh.vertices[loop.vertices[(i + 1) % n]] -
                                       mesh.vertices[loop.vertices[(i + n - 1) % n]])
                                          .cast<double>();
      // Faces lie left of the loop seen from the front: outwards is tangent x normal, which is
      // also in the tangent plane.
      const Eigen::Vector3d outward = tangent.cross(normals[v]);
      if (!(outward.norm() > 0.0)) continue;
      grown[i] = static_cast<int>(mesh.vertices.size());
      mesh.vertices.push_back((p + band * outward.normalized()).cast<float>());
      if (!mesh.colors.empty()) mesh.colors.push_back(mesh.colors[v]);
      cell.source_points.push_back(-1);
      ++stats.vertices;
    }
    for (size_t i = 0; i < n; ++i) {
      const size_t j = (i + 1) % n;
      const int a = loop.vertices[i];
      const int b = loop.vertices[j];
      if (grown[i] >= 0) add_face(a, grown[i], grown[j] >= 0 ? grown[j] : b);
      if (grown[j] >= 0) add_face(a, grown[j], b);
    }
  }
  return stats;
}

}  // namespace avc::surface
