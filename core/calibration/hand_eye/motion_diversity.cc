#include "core/calibration/hand_eye/motion_diversity.h"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace avc::calibration::hand_eye {
namespace {

double Degrees(double radians) { return radians * 180 / std::numbers::pi; }

}  // namespace

MotionDiversity MeasureMotionDiversity(const std::vector<Eigen::Matrix3d>& rotations) {
  MotionDiversity diversity;
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (size_t i = 0; i < rotations.size(); ++i) {
    for (size_t j = i + 1; j < rotations.size(); ++j) {
      const Eigen::AngleAxisd relative(Eigen::Matrix3d(rotations[j] * rotations[i].transpose()));
      const Eigen::Vector3d w = relative.angle() * relative.axis();
      scatter += w * w.transpose();
      diversity.largest_rotation_rad = std::max(diversity.largest_rotation_rad, relative.angle());
    }
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(scatter);
  const double l1 = solver.eigenvalues()(2);
  const double l2 = std::max(0.0, solver.eigenvalues()(1));
  diversity.axis_spread_rad = l1 > 0 ? 2 * std::atan(std::sqrt(l2 / l1)) : 0;
  return diversity;
}

std::string DegeneracyReason(const std::vector<Eigen::Matrix3d>& rotations,
                             const DiversityLimits& limits) {
  if (static_cast<int>(rotations.size()) < limits.min_poses) {
    return fmt::format("too few poses: {} given, at least {} needed", rotations.size(),
                       limits.min_poses);
  }
  const MotionDiversity diversity = MeasureMotionDiversity(rotations);
  if (diversity.largest_rotation_rad < limits.min_largest_rotation_rad) {
    return fmt::format(
        "too little rotation between poses: the largest relative rotation is {:.3g} deg, at "
        "least {:.3g} deg needed",
        Degrees(diversity.largest_rotation_rad), Degrees(limits.min_largest_rotation_rad));
  }
  if (diversity.axis_spread_rad < limits.min_axis_spread_rad) {
    return fmt::format(
        "the relative rotations are all about (nearly) one axis: axis spread {:.3g} deg, at "
        "least {:.3g} deg needed; rotate the camera about at least two different axes",
        Degrees(diversity.axis_spread_rad), Degrees(limits.min_axis_spread_rad));
  }
  return {};
}

}  // namespace avc::calibration::hand_eye
