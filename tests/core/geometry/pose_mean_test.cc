// The mean of several estimates of one pose: symmetric errors cancel, and the result is a rotation.

#include "core/geometry/pose_mean.h"

#include <gtest/gtest.h>

namespace avc::geometry {
namespace {

Eigen::Isometry3d Pose(double angle_z, const Eigen::Vector3d& axis_tilt, const Eigen::Vector3d& t) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = (Eigen::AngleAxisd(angle_z, Eigen::Vector3d::UnitZ()) *
                   Eigen::AngleAxisd(axis_tilt.norm(), axis_tilt.normalized()))
                      .toRotationMatrix();
  pose.translation() = t;
  return pose;
}

TEST(PoseMean, SymmetricErrorsCancelAndTheRotationStaysARotation) {
  const Eigen::Vector3d tilt(0.2, -0.1, 0.05);
  const std::vector<Eigen::Isometry3d> poses = {
      Pose(0.3 + 0.02, tilt, {1.0, 2.0, 3.0}), Pose(0.3 - 0.02, tilt, {1.2, 2.0, 2.8}),
      Pose(0.3, tilt, {0.8, 2.3, 3.1}), Pose(0.3, tilt, {1.0, 1.7, 3.1})};
  const Eigen::Isometry3d mean = PoseMean(poses);
  const Eigen::Isometry3d expected = Pose(0.3, tilt, {1.0, 2.0, 3.0});
  EXPECT_LT(Eigen::AngleAxisd(mean.linear().transpose() * expected.linear()).angle(), 1e-4);
  EXPECT_LT((mean.translation() - expected.translation()).norm(), 1e-12);
  EXPECT_NEAR(mean.linear().determinant(), 1.0, 1e-12);
  EXPECT_LT((mean.linear() * mean.linear().transpose() - Eigen::Matrix3d::Identity()).norm(),
            1e-12);
  EXPECT_TRUE(PoseMean({}).isApprox(Eigen::Isometry3d::Identity()));
}

}  // namespace
}  // namespace avc::geometry
