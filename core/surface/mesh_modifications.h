#pragma once

// Phase 3 of the paper's Algorithm 3 (line 4) on one cell: long triangles and boundary slivers
// removed, small holes filled, then Laplacian smoothing, interior vertices first and boundary
// vertices after.

#include <cstddef>

#include "core/geometry/mesh.h"
#include "core/surface/surface_options.h"

namespace avc::surface {

struct ModificationStats {
  size_t long_triangles = 0;
  size_t slivers = 0;
  size_t holes_filled = 0;

  ModificationStats& operator+=(const ModificationStats& other) {
    long_triangles += other.long_triangles;
    slivers += other.slivers;
    holes_filled += other.holes_filled;
    return *this;
  }
};

ModificationStats ModifyCellMesh(geometry::Mesh& mesh, const SurfaceOptions& options,
                                 const SurfaceThresholds& thresholds);

}  // namespace avc::surface
