// Safety envelope: joint limits, table plane, keep-out cylinder and caps, checked along paths.

#include "core/kinematics/safety_envelope.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/kinematics/forward_kinematics.h"

namespace avc::kinematics {
namespace {

constexpr double kHalfPi = std::numbers::pi / 2;

JointVector Home() {
  return (JointVector() << 0, -kHalfPi, kHalfPi, -kHalfPi, -kHalfPi, 0).finished();
}

TEST(SafetyEnvelope, AllowsAnOrdinaryMove) {
  const SafetyEnvelope envelope;
  ASSERT_EQ(envelope.Validate(), "");
  JointVector to = Home();
  to[0] = 0.5;
  EXPECT_EQ(CheckJointMove(envelope, NominalUr5(), Home(), to, 1.0, 1.0), "");
}

TEST(SafetyEnvelope, RefusesJointLimitsAndCaps) {
  SafetyEnvelope envelope;
  envelope.joint_max[0] = 0.4;
  JointVector to = Home();
  to[0] = 0.5;
  const auto dh = NominalUr5();
  EXPECT_NE(CheckJointMove(envelope, dh, Home(), to, 1.0, 1.0).find("joint 1"), std::string::npos);
  to[0] = 0.3;
  EXPECT_EQ(CheckJointMove(envelope, dh, Home(), to, 1.0, 1.0), "");
  EXPECT_NE(CheckJointMove(envelope, dh, Home(), to, 2.0, 1.0).find("speed"), std::string::npos);
  EXPECT_NE(CheckJointMove(envelope, dh, Home(), to, 1.0, 5.0).find("acceleration"),
            std::string::npos);
  to[3] = NAN;
  EXPECT_NE(CheckJointMove(envelope, dh, Home(), to, 1.0, 1.0), "");
}

TEST(SafetyEnvelope, RefusesGoingBelowTheTable) {
  SafetyEnvelope envelope;
  envelope.table_z_base_m = 0.0;
  const auto dh = NominalUr5();
  // q = 0 stretches the arm horizontally at z ~ -0.005 m: under the table clearance.
  const std::string reason = CheckJointMove(envelope, dh, Home(), JointVector::Zero(), 1.0, 1.0);
  EXPECT_NE(reason.find("below the table plane"), std::string::npos) << reason;
}

TEST(SafetyEnvelope, RefusesAPathThroughTheKeepOutCylinderEvenWhenBothEndsAreClear) {
  const auto dh = NominalUr5();
  const Eigen::Vector3d middle = ForwardKinematics(dh, Home()).translation();
  SafetyEnvelope envelope;
  envelope.keep_out = KeepOutCylinder{middle.head<2>(), 0.08, middle.z() - 0.3, middle.z() + 0.3};
  JointVector from = Home(), to = Home();
  from[0] = -0.6;
  to[0] = 0.6;
  EXPECT_EQ(CheckJointMove(envelope, dh, from, from, 1.0, 1.0), "");
  EXPECT_EQ(CheckJointMove(envelope, dh, to, to, 1.0, 1.0), "");
  const std::string reason = CheckJointMove(envelope, dh, from, to, 1.0, 1.0);
  EXPECT_NE(reason.find("keep-out cylinder"), std::string::npos) << reason;
  // Caught part-way along the path, not at its end.
  const size_t at = reason.find("path:");
  ASSERT_NE(at, std::string::npos) << reason;
  const int percent = std::stoi(reason.substr(reason.find("at ") + 3));
  EXPECT_GT(percent, 20) << reason;
  EXPECT_LT(percent, 60) << reason;
}

TEST(SafetyEnvelope, LinearMoveChecksReachAndReturnsTheEndJoints) {
  const auto dh = NominalUr5();
  const SafetyEnvelope envelope;
  Eigen::Isometry3d goal = ForwardKinematics(dh, Home());
  goal.translation() += Eigen::Vector3d(0.05, -0.05, 0.1);
  JointVector end;
  ASSERT_EQ(CheckLinearMove(envelope, dh, Home(), goal, 0.1, 0.5, &end), "");
  EXPECT_LT((ForwardKinematics(dh, end).translation() - goal.translation()).norm(), 1e-8);
  Eigen::Isometry3d far = goal;
  far.translation() = Eigen::Vector3d(2.0, 0, 0.3);
  EXPECT_NE(CheckLinearMove(envelope, dh, Home(), far, 0.1, 0.5).find("inverse kinematics"),
            std::string::npos);
  Eigen::Isometry3d skewed = goal;
  skewed.linear() *= 1.1;
  EXPECT_NE(CheckLinearMove(envelope, dh, Home(), skewed, 0.1, 0.5).find("not a rigid transform"),
            std::string::npos);
  EXPECT_NE(CheckLinearMove(envelope, dh, Home(), goal, 1.0, 0.5).find("speed"), std::string::npos);
}

}  // namespace
}  // namespace avc::kinematics
