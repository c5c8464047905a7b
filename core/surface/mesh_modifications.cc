#include "core/surface/mesh_modifications.h"

#include "core/surface/hole_filling.h"
#include "core/surface/laplacian_smoothing.h"
#include "core/surface/triangle_cleanup.h"

namespace avc::surface {

ModificationStats ModifyCellMesh(geometry::Mesh& mesh, const SurfaceOptions& options,
                                 const SurfaceThresholds& thresholds) {
  ModificationStats stats;
  stats.long_triangles = RemoveLongTriangles(mesh, thresholds.long_edge);
  stats.slivers = PeelBoundarySlivers(mesh, options.min_boundary_quality);
  stats.holes_filled = FillSmallHoles(mesh, thresholds.hole_perimeter);
  SmoothSheet(mesh, options.cell_smoothing);
  return stats;
}

}  // namespace avc::surface
