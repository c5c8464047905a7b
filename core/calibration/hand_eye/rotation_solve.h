#pragma once

// Rotation part of A_i X = Z B_i by Dornaika & Horaud's unit-quaternion closed form: with
// a_i (x) x = z (x) b_i, minimise sum |Q(a_i) x - W(b_i) z|^2 = 2n - 2 x^T M z over unit x, z,
// M = sum Q(a_i)^T W(b_i); x and z are M's top left and right singular vectors.

#include <Eigen/Core>
#include <vector>

#include "core/calibration/hand_eye/quaternion_matrices.h"

namespace avc::calibration::hand_eye {

struct RotationSolution {
  Eigen::Matrix3d R_X = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d R_Z = Eigen::Matrix3d::Identity();
  // Singular values of M divided by the number of poses, descending: the first is 1 for exact
  // data; a small gap to the second means motions about nearly parallel axes.
  Eigen::Vector4d normalised_singular_values = Eigen::Vector4d::Zero();
};

// The closed form on quaternions taken with the signs given (no sign alignment): exact only when
// every a_i (x) x = +z (x) b_i with one common sign. Sizes must match and be non-zero.
RotationSolution SolveRotationFromQuaternions(const std::vector<QuaternionVector>& a,
                                              const std::vector<QuaternionVector>& b);

// The closed form for rotation matrices R_A,i and R_B,i: converts to quaternions, aligns their
// signs (AlignQuaternionSigns) and solves.
RotationSolution SolveRotation(const std::vector<Eigen::Matrix3d>& R_A,
                               const std::vector<Eigen::Matrix3d>& R_B);

}  // namespace avc::calibration::hand_eye
