#pragma once

// A cell: one piece of a cluster triangulated on its regression plane and lifted back onto the
// original points (paper §4, Phase 1). Phase 2 grows its outline (new vertices have
// source_points -1), Phase 3 smooths and repairs it, and a cell Phase 3 leaves in several
// pieces becomes one cell per piece (cell_islands.h) before Phase 4 stitches cells together.

#include <cstdint>
#include <vector>

#include "core/geometry/mesh.h"
#include "core/surface/plane_frame.h"

namespace avc::surface {

struct Cell {
  int32_t cluster = -1;
  PlaneFrame plane;  // normal oriented with the points' normals
  // vertices (m), faces oriented so their front faces along plane.normal, colours when the input
  // had them, face_labels = cluster.
  geometry::Mesh mesh;
  std::vector<int32_t> source_points;  // per vertex: input point index, -1 for generated ones
};

}  // namespace avc::surface
