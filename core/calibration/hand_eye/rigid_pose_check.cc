#include "core/calibration/hand_eye/rigid_pose_check.h"

#include <fmt/format.h>

namespace avc::calibration::hand_eye {

std::string RigidPoseError(const Eigen::Isometry3d& pose, const std::string& name) {
  if (!pose.matrix().allFinite()) return name + " is not finite (NaN or infinity)";
  const Eigen::Matrix3d rotation = pose.linear();
  const double orthogonality =
      (rotation * rotation.transpose() - Eigen::Matrix3d::Identity()).norm();
  if (orthogonality > kOrthogonalityTolerance) {
    return fmt::format("{} is not rigid: its rotation block has |R R^T - I| = {:.3g}", name,
                       orthogonality);
  }
  if (rotation.determinant() < 0) return name + " is a reflection (determinant -1), not a rotation";
  if (pose.matrix().row(3) != Eigen::RowVector4d(0, 0, 0, 1)) {
    return name + " has a bottom row other than 0 0 0 1";
  }
  return {};
}

}  // namespace avc::calibration::hand_eye
