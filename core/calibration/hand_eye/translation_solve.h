#pragma once

// Translation part of A_i X = Z B_i once R_Z is known: R_A,i t_X + t_A,i = R_Z t_B,i + t_Z gives
// the linear least-squares system [R_A,i  -I] [t_X; t_Z] = R_Z t_B,i - t_A,i (3n x 6).

#include <Eigen/Core>
#include <vector>

namespace avc::calibration::hand_eye {

struct TranslationSolution {
  Eigen::Vector3d t_X = Eigen::Vector3d::Zero();
  Eigen::Vector3d t_Z = Eigen::Vector3d::Zero();
};

// Solved by column-pivoting QR. Sizes must match and be at least 2 (the rotations must differ
// for the system to have full rank, which the degeneracy check guarantees).
TranslationSolution SolveTranslation(const std::vector<Eigen::Matrix3d>& R_A,
                                     const std::vector<Eigen::Vector3d>& t_A,
                                     const std::vector<Eigen::Vector3d>& t_B,
                                     const Eigen::Matrix3d& R_Z);

}  // namespace avc::calibration::hand_eye
