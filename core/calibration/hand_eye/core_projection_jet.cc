#include "core/calibration/hand_eye/core_projection_jet.h"

namespace avc::calibration::hand_eye {

Eigen::Matrix2d DistortionJacobian(const camera::Intrinsics& intrinsics,
                                   const Eigen::Vector2d& normalised) {
  // Step ~ cube root of machine epsilon balances truncation and rounding error.
  constexpr double kStep = 6e-6;
  Eigen::Matrix2d jacobian;
  for (int column = 0; column < 2; ++column) {
    Eigen::Vector2d step = Eigen::Vector2d::Zero();
    step(column) = kStep;
    jacobian.col(column) =
        (intrinsics.Distort(normalised + step) - intrinsics.Distort(normalised - step)) /
        (2 * kStep);
  }
  return jacobian;
}

}  // namespace avc::calibration::hand_eye
