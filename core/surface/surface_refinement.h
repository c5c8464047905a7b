#pragma once

// Phase 3's last step on one cell: the mesh is subdivided and every vertex moved onto the
// surface fitted to the cell's own samples (fitted_surface.h). Vertices then lie on the
// averaged surface instead of on single noisy samples, and the chords between samples follow
// the leaf's curvature; grown outline vertices, which have no sample, are projected onto the
// fit's continuation. Only the cell's samples are used, so a leaf crossing another is not
// pulled towards it.

#include <Eigen/Core>
#include <vector>

#include "core/surface/cell.h"
#include "core/surface/fitted_surface.h"

namespace avc::surface {

struct RefinementStats {
  size_t vertices_added = 0;      // by subdivision
  size_t vertices_projected = 0;  // moved onto the fitted surface
  size_t vertices_kept = 0;       // too few samples near to fit; left where they were

  RefinementStats& operator+=(const RefinementStats& other) {
    vertices_added += other.vertices_added;
    vertices_projected += other.vertices_projected;
    vertices_kept += other.vertices_kept;
    return *this;
  }
};

// samples: the input positions that cell.source_points index. subdivisions: 1-to-4 midpoint
// subdivisions before the projection (0: project the vertices only).
RefinementStats RefineCell(Cell& cell, const std::vector<Eigen::Vector3f>& samples, double spacing,
                           int subdivisions, const FittedSurfaceOptions& fit);

}  // namespace avc::surface
