#pragma once

// Volume of the convex hull of a point set (CGAL quickhull), the plant's "hull volume" trait.

#include <Eigen/Core>
#include <vector>

namespace avc::traits {

// m^3; 0 for fewer than 4 points or points that span no volume (coplanar, collinear).
double ConvexHullVolume(const std::vector<Eigen::Vector3f>& points);

}  // namespace avc::traits
