#pragma once

// How URScript, RTDE and the primary interface write a pose: p[x, y, z, rx, ry, rz], metres and
// a rotation vector (axis * angle, radians), as a transform and back.

#include <Eigen/Geometry>
#include <array>

namespace avc::robot {

// Rotation vector (axis * angle) as a rotation matrix, and a UR pose vector as a transform.
Eigen::Matrix3d RotationFromVector(const Eigen::Vector3d& rotation_vector);
Eigen::Isometry3d PoseFromVector(const std::array<double, 6>& pose);
std::array<double, 6> VectorFromPose(const Eigen::Isometry3d& pose);

}  // namespace avc::robot
