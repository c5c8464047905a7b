#include "core/geometry/pose_mean.h"

#include <Eigen/SVD>

namespace avc::geometry {

Eigen::Isometry3d PoseMean(const std::vector<Eigen::Isometry3d>& poses) {
  Eigen::Isometry3d mean = Eigen::Isometry3d::Identity();
  if (poses.empty()) return mean;
  Eigen::Matrix3d rotation_sum = Eigen::Matrix3d::Zero();
  Eigen::Vector3d translation_sum = Eigen::Vector3d::Zero();
  for (const Eigen::Isometry3d& pose : poses) {
    rotation_sum += pose.linear();
    translation_sum += pose.translation();
  }
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(rotation_sum,
                                              Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d sign = Eigen::Matrix3d::Identity();
  sign(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0 ? -1 : 1;
  mean.linear() = svd.matrixU() * sign * svd.matrixV().transpose();
  mean.translation() = translation_sum / static_cast<double>(poses.size());
  return mean;
}

}  // namespace avc::geometry
