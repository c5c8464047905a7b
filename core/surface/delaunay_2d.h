#pragma once

// 2-D Delaunay triangulation (CGAL, exact predicates), kept behind this one function so the rest
// of the surfacer has no CGAL types.

#include <Eigen/Core>
#include <vector>

namespace avc::surface {

// Triangles as indices into points, counter-clockwise. Of coincident points only one is used.
// Fewer than 3 points or all collinear give no triangles. Deterministic: same points, same
// triangles in the same order.
std::vector<Eigen::Vector3i> Delaunay2d(const std::vector<Eigen::Vector2d>& points);

}  // namespace avc::surface
