#include "core/calibration/hand_eye/rotation_solve.h"

#include <Eigen/SVD>
#include <stdexcept>

#include "core/calibration/hand_eye/quaternion_sign_alignment.h"

namespace avc::calibration::hand_eye {

RotationSolution SolveRotationFromQuaternions(const std::vector<QuaternionVector>& a,
                                              const std::vector<QuaternionVector>& b) {
  if (a.size() != b.size() || a.empty()) {
    throw std::invalid_argument("SolveRotationFromQuaternions: need equally many, non-zero a, b");
  }
  Eigen::Matrix4d M = Eigen::Matrix4d::Zero();
  for (size_t i = 0; i < a.size(); ++i) {
    M += LeftProductMatrix(a[i]).transpose() * RightProductMatrix(b[i]);
  }
  // Dynamic-size SVD: GCC 12 reports a false maybe-uninitialized inside the fixed-size 4x4 one.
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(Eigen::MatrixXd(M),
                                              Eigen::ComputeFullU | Eigen::ComputeFullV);
  RotationSolution solution;
  solution.R_X = RotationOfQuaternion(QuaternionVector(svd.matrixU().col(0)));
  solution.R_Z = RotationOfQuaternion(QuaternionVector(svd.matrixV().col(0)));
  solution.normalised_singular_values =
      Eigen::Vector4d(svd.singularValues()) / static_cast<double>(a.size());
  return solution;
}

RotationSolution SolveRotation(const std::vector<Eigen::Matrix3d>& R_A,
                               const std::vector<Eigen::Matrix3d>& R_B) {
  if (R_A.size() != R_B.size()) {
    throw std::invalid_argument("SolveRotation: R_A and R_B differ in size");
  }
  std::vector<QuaternionVector> a, b;
  for (size_t i = 0; i < R_A.size(); ++i) {
    a.push_back(QuaternionOfRotation(R_A[i]));
    b.push_back(QuaternionOfRotation(R_B[i]));
  }
  return SolveRotationFromQuaternions(a, AlignQuaternionSigns(a, b));
}

}  // namespace avc::calibration::hand_eye
