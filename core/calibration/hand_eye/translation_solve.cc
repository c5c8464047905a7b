#include "core/calibration/hand_eye/translation_solve.h"

#include <Eigen/QR>
#include <stdexcept>

namespace avc::calibration::hand_eye {

TranslationSolution SolveTranslation(const std::vector<Eigen::Matrix3d>& R_A,
                                     const std::vector<Eigen::Vector3d>& t_A,
                                     const std::vector<Eigen::Vector3d>& t_B,
                                     const Eigen::Matrix3d& R_Z) {
  const size_t n = R_A.size();
  if (t_A.size() != n || t_B.size() != n || n < 2) {
    throw std::invalid_argument("SolveTranslation: need at least 2 poses with matching sizes");
  }
  Eigen::MatrixXd system(3 * n, 6);
  Eigen::VectorXd rhs(3 * n);
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Index row = static_cast<Eigen::Index>(3 * i);
    system.block<3, 3>(row, 0) = R_A[i];
    system.block<3, 3>(row, 3) = -Eigen::Matrix3d::Identity();
    rhs.segment<3>(row) = R_Z * t_B[i] - t_A[i];
  }
  const Eigen::VectorXd solution = system.colPivHouseholderQr().solve(rhs);
  return {solution.head<3>(), solution.tail<3>()};
}

}  // namespace avc::calibration::hand_eye
