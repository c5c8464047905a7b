#pragma once

// The project's camera model (camera::Intrinsics) evaluated on Ceres jets, so the refinement
// optimises exactly the projection every other module uses: the value always comes from
// Intrinsics::Distort; the derivative of the distortion is its central difference (a 2x2
// Jacobian in normalised coordinates, accurate to ~1e-10), chained onto the jet's derivatives.

#include <ceres/jet.h>

#include <Eigen/Core>

#include "core/camera/pinhole_camera.h"

namespace avc::calibration::hand_eye {

// d Distort / d normalised at `normalised`.
Eigen::Matrix2d DistortionJacobian(const camera::Intrinsics& intrinsics,
                                   const Eigen::Vector2d& normalised);

inline Eigen::Vector2d DistortForCeres(const camera::Intrinsics& intrinsics,
                                       const Eigen::Vector2d& normalised) {
  return intrinsics.Distort(normalised);
}

template <int N>
Eigen::Matrix<ceres::Jet<double, N>, 2, 1> DistortForCeres(
    const camera::Intrinsics& intrinsics,
    const Eigen::Matrix<ceres::Jet<double, N>, 2, 1>& normalised) {
  const Eigen::Vector2d value(normalised.x().a, normalised.y().a);
  const Eigen::Vector2d distorted = intrinsics.Distort(value);
  const Eigen::Matrix2d jacobian = DistortionJacobian(intrinsics, value);
  Eigen::Matrix<ceres::Jet<double, N>, 2, 1> result;
  for (int row = 0; row < 2; ++row) {
    result(row).a = distorted(row);
    result(row).v = jacobian(row, 0) * normalised.x().v + jacobian(row, 1) * normalised.y().v;
  }
  return result;
}

}  // namespace avc::calibration::hand_eye
