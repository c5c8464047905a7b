#pragma once

// Phase 3 hole filling (paper §4): closed boundary loops that are not the outer boundary of
// their piece of surface and are short (perimeter <= max_perimeter) are holes; each is closed by
// a fan round a new vertex at the loop's centroid (one triangle for a three-edge hole). The new
// faces take the label of the face along the loop's first edge, the new vertex the mean colour.

#include <cstddef>

#include "core/geometry/mesh.h"

namespace avc::surface {

// Returns the number of holes filled. New vertices are appended at the end.
size_t FillSmallHoles(geometry::Mesh& mesh, double max_perimeter);

}  // namespace avc::surface
