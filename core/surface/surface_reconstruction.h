#pragma once

// The surfacer (paper §4, Algorithm 3) from a clustered merged point cloud to one mesh:
//  Phase 1 (triangulate_cell.h): each cluster triangulated on its regression plane -> a cell.
//  Phase 2 (image_growth.h): with the scan's images, each cell's outline grows as a level set
//          over its plane where the plant masks see leaf, up to its neighbours; without images
//          (boundary_growth.h), outlines grow by the band the sampling leaves at an edge.
//  Phase 3 (mesh_modifications.h): long triangles and slivers removed, small holes filled,
//          Laplacian smoothing (interior, then boundary); then each cell subdivided and moved
//          onto the surface fitted to its samples (surface_refinement.h).
//  Phase 4 (cell_merging.h): neighbouring cells stitched into a connected surface (a cell that
//          Phase 3 left in pieces counts as one cell per piece, cell_islands.h); the holes
//          left where several cells meet are filled, then a final smoothing.
// Thresholds are multiples of the measured point spacing (surface_options.h). The output's
// face_labels hold the cluster id of each face, colours are the points' when given.
// Deterministic: no randomness, no threads, every step in index order.

#include <cstddef>
#include <string>
#include <vector>

#include "core/geometry/mesh.h"
#include "core/surface/cell_merging.h"
#include "core/surface/clustered_points.h"
#include "core/surface/image_evidence.h"
#include "core/surface/image_growth.h"
#include "core/surface/mesh_modifications.h"
#include "core/surface/surface_options.h"
#include "core/surface/surface_refinement.h"

namespace avc::surface {

struct SurfaceReport {
  SurfaceThresholds thresholds;  // in force (m)
  size_t input_points = 0;
  size_t used_points = 0;  // assigned and finite
  size_t clusters = 0;
  size_t cells = 0;            // triangulated pieces of clusters (cell.h)
  size_t cell_islands = 0;     // ... of which split off a cell by Phase 3 (cell_islands.h)
  size_t points_left_out = 0;  // usable points in pieces that could not be triangulated
  size_t phase1_faces = 0;     // Delaunay triangles kept by alpha
  size_t grown_vertices = 0;   // vertices added by the growth (either kind)
  size_t image_views = 0;      // views Phase 2 grew with (0: the band growth without images)
  ImageGrowthStats image_growth;
  ModificationStats modifications;
  RefinementStats refinement;
  StitchStats stitching;
  size_t merged_holes_filled = 0;
  size_t fragments_removed = 0;  // pieces below min_component_faces
  // Surface area (m^2) after each step: where area is won or lost.
  double area_triangulated = 0;  // Phase 1
  double area_grown = 0;         // Phase 2
  double area_modified = 0;      // Phase 3
  double area_stitched = 0;      // Phase 4 stitching
  double area = 0;               // final
  size_t vertices = 0;
  size_t faces = 0;
  int components = 0;
  // Clusters left out and input problems, one sentence each.
  std::vector<std::string> warnings;
};

struct SurfaceResult {
  geometry::Mesh mesh;
  SurfaceReport report;
};

// Throws std::invalid_argument for inconsistent input (clustered_points.h) or invalid options.
// Input that cannot be surfaced (no cluster with 3 usable points, collinear clusters, NaNs)
// gives warnings and a mesh of whatever could be made, possibly empty. images: the scan's views
// with plant masks for Phase 2 (nullptr or none: the band growth); a mask that does not fit its
// camera throws std::invalid_argument naming the view.
SurfaceResult ReconstructSurface(const ClusteredPoints& input, const SurfaceOptions& options = {},
                                 const SurfaceImages* images = nullptr);

}  // namespace avc::surface
