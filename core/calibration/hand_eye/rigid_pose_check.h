#pragma once

// Input checks shared by the solvers: a pose must be a finite rigid transform.

#include <Eigen/Geometry>
#include <string>

namespace avc::calibration::hand_eye {

// Rotation blocks whose |R R^T - I| (Frobenius) exceeds this are not rotations. Loose enough for
// poses converted from rotation vectors or printed to 9 digits, tight enough to catch a scaled or
// sheared matrix.
inline constexpr double kOrthogonalityTolerance = 1e-6;

// Empty when `pose` is finite, its rotation block orthonormal with determinant +1 and its bottom
// row 0 0 0 1; else what is wrong, prefixed with `name` (e.g. "pose 3 T_base_flange").
std::string RigidPoseError(const Eigen::Isometry3d& pose, const std::string& name);

}  // namespace avc::calibration::hand_eye
