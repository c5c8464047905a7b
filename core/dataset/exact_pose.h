#pragma once

// A world-to-camera pose from a rotation matrix and a translation as datasets print them: the
// printed digits make R only nearly orthonormal, so it is re-orthonormalised to make the pose an
// exact isometry; a matrix that is no rotation at all gives nullopt for the caller to report.

#include <Eigen/Geometry>
#include <optional>

namespace avc::dataset {

std::optional<Eigen::Isometry3d> ExactPose(const Eigen::Matrix3d& r, const Eigen::Vector3d& t);

}  // namespace avc::dataset
