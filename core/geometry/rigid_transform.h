#pragma once

// The one check that a 4x4 transform is a rigid motion (a pose, a calibration, a frame change),
// with a message that says what is wrong. Shared by every reader and solver that takes poses.

#include <Eigen/Geometry>
#include <string>

namespace avc::geometry {

// |R R^T - I| (Frobenius) above this is not a rotation: loose enough for poses converted from
// rotation vectors or printed to 9 digits, tight enough to catch a scaled or sheared matrix.
inline constexpr double kRigidTolerance = 1e-6;

// Empty when `transform` is finite, its rotation block orthonormal within `tolerance` with
// determinant +1 and its bottom row 0 0 0 1; else "<name> is not a rigid transform: <why>".
std::string RigidTransformProblem(const Eigen::Isometry3d& transform, const std::string& name,
                                  double tolerance = kRigidTolerance);

}  // namespace avc::geometry
