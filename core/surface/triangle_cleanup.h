#pragma once

// Phase 3 mesh modifications (paper §4): removal of long triangles (lifted across a fold or a
// gap) and of the thin slivers a Delaunay triangulation leaves along its boundary.

#include <cstddef>

#include "core/geometry/mesh.h"

namespace avc::surface {

// Removes faces with a 3-D edge longer than max_edge. Returns how many.
size_t RemoveLongTriangles(geometry::Mesh& mesh, double max_edge);

// Repeatedly peels boundary faces (a face with an edge on the boundary) whose quality
// (mesh_topology.h) is below min_quality, until none is left. Returns how many.
size_t PeelBoundarySlivers(geometry::Mesh& mesh, double min_quality);

}  // namespace avc::surface
