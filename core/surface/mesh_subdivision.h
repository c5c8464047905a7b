#pragma once

// Midpoint subdivision: every triangle into four, a new vertex at the middle of each edge
// (shared by the edge's two faces), attributes carried over (vertex colours and uvs averaged
// along the edge, face labels and materials copied to the four children).

#include <vector>

#include "core/geometry/mesh.h"

namespace avc::surface {

// Returns the number of vertices added. source_points, when given, gets -1 for each one.
size_t SubdivideMidpoints(geometry::Mesh& mesh, std::vector<int32_t>* source_points = nullptr);

}  // namespace avc::surface
