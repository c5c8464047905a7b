#include "core/kinematics/forward_kinematics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "core/kinematics/dh_parameters.h"
#include "core/kinematics/pose_difference.h"

namespace avc::kinematics {
namespace {

constexpr double kPi = std::numbers::pi;

// Uniform in [-limit, limit] from raw engine bits (bit-identical across standard libraries).
JointVector RandomJoints(std::mt19937_64& rng, double limit) {
  JointVector q;
  for (int i = 0; i < 6; ++i)
    q[i] = limit * (2.0 * static_cast<double>(rng() >> 11) * 0x1.0p-53 - 1.0);
  return q;
}

// Rotation by `angle` about the line through `point` along unit `axis`.
Eigen::Isometry3d ScrewMotion(const Eigen::Vector3d& axis, const Eigen::Vector3d& point,
                              double angle) {
  return Eigen::Translation3d(point) * Eigen::AngleAxisd(angle, axis) *
         Eigen::Translation3d(-point);
}

// Product of exponentials with joint axes and home pose worked out by hand for the nominal UR5
// at q = 0 (independent of the DH code): T(q) = exp(S1 q1) ... exp(S6 q6) M.
Eigen::Isometry3d ProductOfExponentialsUr5(const JointVector& q) {
  const double d1 = 0.089159, a2 = -0.425, a3 = -0.39225, d4 = 0.10915, d5 = 0.09465, d6 = 0.0823;
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ(), minus_y = -Eigen::Vector3d::UnitY();
  const Eigen::Vector3d axes[6] = {up, minus_y, minus_y, minus_y, -up, minus_y};
  const Eigen::Vector3d points[6] = {{0, 0, 0},        {0, 0, d1},         {a2, 0, d1},
                                     {a2 + a3, 0, d1}, {a2 + a3, -d4, d1}, {a2 + a3, -d4, d1 - d5}};
  Eigen::Isometry3d home = Eigen::Isometry3d::Identity();
  home.linear() = Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  home.translation() << a2 + a3, -d4 - d6, d1 - d5;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  for (int i = 0; i < 6; ++i) pose = pose * ScrewMotion(axes[i], points[i], q[i]);
  return pose * home;
}

TEST(ForwardKinematics, ZeroPoseMatchesPublishedVector) {
  const Eigen::Isometry3d flange = ForwardKinematics(NominalUr5(), JointVector::Zero());
  // Universal Robots' published UR5 (CB3) DH parameters: p = (a2 + a3, -(d4 + d6), d1 - d5),
  // rotation vector (pi/2, 0, 0).
  EXPECT_NEAR(flange.translation().x(), -0.81725, 1e-12);
  EXPECT_NEAR(flange.translation().y(), -0.19145, 1e-12);
  EXPECT_NEAR(flange.translation().z(), 0.089159 - 0.09465, 1e-12);
  const Eigen::AngleAxisd rotation(Eigen::Matrix3d(flange.linear()));
  EXPECT_NEAR(rotation.angle(), kPi / 2, 1e-12);
  EXPECT_NEAR(rotation.axis().x(), 1.0, 1e-12);
}

TEST(ForwardKinematics, UprightPoseMatchesPublishedVector) {
  JointVector q;
  q << 0, -kPi / 2, 0, -kPi / 2, 0, 0;
  const Eigen::Vector3d p = ForwardKinematics(NominalUr5(), q).translation();
  EXPECT_NEAR(p.x(), 0.0, 1e-12);
  EXPECT_NEAR(p.y(), -0.19145, 1e-12);
  EXPECT_NEAR(p.z(), 0.089159 + 0.425 + 0.39225 + 0.09465, 1e-12);  // 1.001059
}

TEST(ForwardKinematics, AgreesWithProductOfExponentials) {
  std::mt19937_64 rng(11);
  const DhParameters dh = NominalUr5();
  for (int trial = 0; trial < 500; ++trial) {
    const JointVector q = RandomJoints(rng, 2 * kPi);
    const PoseDifference difference =
        ComparePoses(ForwardKinematics(dh, q), ProductOfExponentialsUr5(q));
    ASSERT_LT(difference.translation_m, 1e-12) << "trial " << trial;
    ASSERT_LT(difference.rotation_rad, 1e-12) << "trial " << trial;
  }
}

TEST(ForwardKinematics, ThetaOffsetShiftsTheJoint) {
  DhParameters shifted = NominalUr5();
  shifted.theta_offset << 0.1, -0.2, 0.3, 0, 0.05, -0.4;
  JointVector q;
  q << 0.5, -1.0, 1.2, -0.3, 0.8, 2.0;
  const PoseDifference difference = ComparePoses(
      ForwardKinematics(shifted, q), ForwardKinematics(NominalUr5(), q + shifted.theta_offset));
  EXPECT_LT(difference.translation_m, 1e-14);
  EXPECT_LT(difference.rotation_rad, 1e-14);
}

TEST(ForwardKinematics, JointFramesChainToTheFlange) {
  JointVector q;
  q << 0.3, -1.1, 1.4, -0.6, 1.2, -2.5;
  const DhParameters dh = NominalUr5();
  const auto frames = JointFrames(dh, q);
  EXPECT_TRUE(frames[0].isApprox(Eigen::Isometry3d::Identity()));
  EXPECT_TRUE(frames[6].isApprox(ForwardKinematics(dh, q), 1e-15));
  // Joint i turns about frame i-1's z axis: rotating joint 3 leaves frame 2 untouched and moves
  // frame 3's origin on a circle about frame 2's z axis.
  JointVector moved = q;
  moved[2] += 0.7;
  const auto moved_frames = JointFrames(dh, moved);
  EXPECT_TRUE(moved_frames[2].isApprox(frames[2], 1e-15));
  const Eigen::Vector3d axis = frames[2].linear().col(2), origin = frames[2].translation();
  const Eigen::Vector3d before = frames[3].translation() - origin,
                        after = moved_frames[3].translation() - origin;
  EXPECT_NEAR(before.cross(after).dot(axis) / before.squaredNorm(), std::sin(0.7), 1e-12);
}

TEST(ForwardKinematics, JacobianMatchesFiniteDifferences) {
  JointVector q;
  q << -0.4, -1.3, 1.9, -2.2, -0.9, 0.6;
  const DhParameters dh = NominalUr5();
  const Eigen::Matrix<double, 6, 6> jacobian = GeometricJacobian(dh, q);
  const Eigen::Isometry3d base_pose = ForwardKinematics(dh, q);
  constexpr double kStep = 1e-7;
  for (int i = 0; i < 6; ++i) {
    JointVector nudged = q;
    nudged[i] += kStep;
    const Eigen::Isometry3d pose = ForwardKinematics(dh, nudged);
    const Eigen::Vector3d linear = (pose.translation() - base_pose.translation()) / kStep;
    const Eigen::AngleAxisd turn(Eigen::Matrix3d(pose.linear() * base_pose.linear().transpose()));
    const Eigen::Vector3d angular = turn.angle() * turn.axis() / kStep;
    EXPECT_LT((linear - jacobian.block<3, 1>(0, i)).norm(), 1e-6) << "joint " << i + 1;
    EXPECT_LT((angular - jacobian.block<3, 1>(3, i)).norm(), 1e-6) << "joint " << i + 1;
  }
}

TEST(DhParameters, ValidationNamesTheBadEntry) {
  DhParameters dh = NominalUr5();
  EXPECT_EQ(dh.Validate(), "");
  dh.alpha[3] = std::nan("");
  EXPECT_NE(dh.Validate().find("alpha[4]"), std::string::npos);
}

TEST(DhParameters, WrapAngleLandsInHalfOpenInterval) {
  EXPECT_DOUBLE_EQ(WrapAngle(kPi), kPi);
  EXPECT_DOUBLE_EQ(WrapAngle(-kPi), kPi);
  EXPECT_NEAR(WrapAngle(3 * kPi / 2), -kPi / 2, 1e-15);
  EXPECT_NEAR(WrapAngle(-7.0), -7.0 + 2 * kPi, 1e-15);
  EXPECT_DOUBLE_EQ(WrapAngle(0.25), 0.25);
}

TEST(DhParameters, JointLimitsAreTwoTurns) {
  JointVector q = JointVector::Constant(2 * kPi);
  EXPECT_TRUE(WithinJointLimits(q));
  EXPECT_EQ(ValidateJoints(q), "");
  q[4] = 2 * kPi + 1e-9;
  EXPECT_FALSE(WithinJointLimits(q));
  EXPECT_NE(ValidateJoints(q).find("joint 5"), std::string::npos);
  q[4] = std::nan("");
  EXPECT_FALSE(WithinJointLimits(q));
  EXPECT_NE(ValidateJoints(q).find("joint 5 is not finite"), std::string::npos);
}

}  // namespace
}  // namespace avc::kinematics
