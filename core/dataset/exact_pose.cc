#include "core/dataset/exact_pose.h"

namespace avc::dataset {

std::optional<Eigen::Isometry3d> ExactPose(const Eigen::Matrix3d& r, const Eigen::Vector3d& t) {
  if (!r.allFinite() || !t.allFinite()) return std::nullopt;
  if ((r.transpose() * r - Eigen::Matrix3d::Identity()).norm() > 1e-5 || r.determinant() < 0) {
    return std::nullopt;
  }
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::Quaterniond(r).normalized().toRotationMatrix();
  pose.translation() = t;
  return pose;
}

}  // namespace avc::dataset
