#pragma once

// The mean of several estimates of one pose: the rotation nearest (Frobenius) the sum of their
// rotation matrices (the chordal L2 mean) and the mean translation. For a fixed frame computed
// from each of several shots.

#include <Eigen/Geometry>
#include <vector>

namespace avc::geometry {

// Identity for no poses.
Eigen::Isometry3d PoseMean(const std::vector<Eigen::Isometry3d>& poses);

}  // namespace avc::geometry
