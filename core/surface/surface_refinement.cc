#include "core/surface/surface_refinement.h"

#include "core/surface/mesh_subdivision.h"

namespace avc::surface {

RefinementStats RefineCell(Cell& cell, const std::vector<Eigen::Vector3f>& samples, double spacing,
                           int subdivisions, const FittedSurfaceOptions& fit) {
  RefinementStats stats;
  std::vector<Eigen::Vector3f> own;
  for (int32_t i : cell.source_points) {
    if (i >= 0) own.push_back(samples[i]);
  }
  if (own.size() < 3 || cell.mesh.faces.empty()) {
    stats.vertices_kept = cell.mesh.vertices.size();
    return stats;
  }
  for (int s = 0; s < subdivisions; ++s) {
    stats.vertices_added += SubdivideMidpoints(cell.mesh, &cell.source_points);
  }
  const FittedSurface surface(std::move(own), cell.plane.normal, spacing, fit);
  for (Eigen::Vector3f& vertex : cell.mesh.vertices) {
    if (const auto projected = surface.Project(vertex)) {
      vertex = *projected;
      ++stats.vertices_projected;
    } else {
      ++stats.vertices_kept;
    }
  }
  return stats;
}

}  // namespace avc::surface
