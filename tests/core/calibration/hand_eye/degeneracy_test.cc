// Refusals before solving: too few poses, too little rotation, rotations about one axis, and bad
// poses named by their index.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "core/calibration/hand_eye/robot_world_hand_eye.h"
#include "core/util/ordered_draws.h"
#include "tests/core/calibration/hand_eye/hand_eye_test_util.h"

namespace avc::calibration::hand_eye {
namespace {

// Observations consistent with fixed X, Z for the given robot poses.
std::vector<HandEyeObservation> Observe(const std::vector<Eigen::Isometry3d>& T_base_flange) {
  sim::DeterministicRandom random(5);
  const Eigen::Isometry3d T_board_base = testing::RandomPose(random, 0.8);
  const Eigen::Isometry3d T_cam_flange = testing::RandomPose(random, 0.15);
  std::vector<HandEyeObservation> observations;
  for (const Eigen::Isometry3d& pose : T_base_flange) {
    observations.push_back({pose, T_cam_flange * pose.inverse() * T_board_base.inverse()});
  }
  return observations;
}

Eigen::Isometry3d Pose(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = rotation;
  pose.translation() = translation;
  return pose;
}

// The message of the DegenerateMotionError `observations` raise ("" if none).
std::string Refusal(const std::vector<HandEyeObservation>& observations) {
  try {
    SolveRobotWorldHandEye(observations);
  } catch (const DegenerateMotionError& error) {
    return error.what();
  }
  return "";
}

std::vector<Eigen::Isometry3d> GoodPoses() {
  sim::DeterministicRandom random(9);
  std::vector<Eigen::Isometry3d> poses;
  for (int i = 0; i < 6; ++i) poses.push_back(testing::RandomPose(random, 0.5));
  return poses;
}

TEST(HandEyeDegeneracy, RefusesFewerThanThreePoses) {
  std::vector<Eigen::Isometry3d> poses = GoodPoses();
  poses.resize(2);
  EXPECT_NE(Refusal(Observe(poses)).find("too few poses: 2 given, at least 3"), std::string::npos);
  EXPECT_NE(Refusal({}).find("too few poses: 0 given"), std::string::npos);
}

TEST(HandEyeDegeneracy, RefusesRotationsAboutOneAxis) {
  // Only the last wrist joint turns: every relative rotation is about the flange z axis, so the
  // hand-eye rotation about it is undetermined. Translations vary freely.
  const Eigen::Isometry3d start = GoodPoses()[0];
  std::vector<Eigen::Isometry3d> poses;
  for (int i = 0; i < 6; ++i) {
    poses.push_back(start *
                    Pose(Eigen::AngleAxisd(i * 25 * testing::kDegree, Eigen::Vector3d::UnitZ())
                             .toRotationMatrix(),
                         Eigen::Vector3d(0.01 * i, -0.02 * i, 0.03 * (i % 2))));
  }
  const std::string reason = Refusal(Observe(poses));
  EXPECT_NE(reason.find("all about (nearly) one axis"), std::string::npos) << reason;
  // Only the base turns: one axis in the base frame instead.
  poses.clear();
  for (int i = 0; i < 5; ++i) {
    poses.push_back(Pose(Eigen::AngleAxisd(i * 30 * testing::kDegree, Eigen::Vector3d::UnitZ())
                             .toRotationMatrix(),
                         Eigen::Vector3d::Zero()) *
                    start);
  }
  EXPECT_NE(Refusal(Observe(poses)).find("one axis"), std::string::npos);
  // A second, clearly different axis lifts the refusal.
  poses.push_back(
      start *
      Pose(Eigen::AngleAxisd(30 * testing::kDegree, Eigen::Vector3d::UnitX()).toRotationMatrix(),
           Eigen::Vector3d::Zero()));
  EXPECT_EQ(Refusal(Observe(poses)), "");
}

TEST(HandEyeDegeneracy, RefusesTooLittleRotation) {
  sim::DeterministicRandom random(4);
  const Eigen::Isometry3d start = GoodPoses()[1];
  std::vector<Eigen::Isometry3d> poses;
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d t =
        util::DrawVector3<Eigen::Vector3d>([&] { return random.Symmetric(0.2); });
    poses.push_back(start * Pose(testing::RandomRotation(random, 1.5 * testing::kDegree), t));
  }
  const std::string reason = Refusal(Observe(poses));
  EXPECT_NE(reason.find("too little rotation"), std::string::npos) << reason;
}

TEST(HandEyeDegeneracy, ReportsDiversityOfAcceptedPoses) {
  const HandEyeSolution solution = SolveRobotWorldHandEye(Observe(GoodPoses()));
  EXPECT_GT(solution.diversity.largest_rotation_rad, 5 * testing::kDegree);
  EXPECT_GT(solution.diversity.axis_spread_rad, 5 * testing::kDegree);
}

TEST(HandEyeDegeneracy, MeasuresTheAngleBetweenTwoAxes) {
  // Rotations about one axis spread 0; about x and z (whose pair difference mixes both) the
  // spread lies between the two single axes' 90 deg apart and 0.
  const Eigen::Matrix3d x = Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Eigen::Matrix3d z = Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Matrix3d z2 = Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  EXPECT_NEAR(MeasureMotionDiversity({Eigen::Matrix3d::Identity(), z, z2}).axis_spread_rad, 0,
              1e-7);
  EXPECT_NEAR(MeasureMotionDiversity({Eigen::Matrix3d::Identity(), z, z2}).largest_rotation_rad,
              1.0, 1e-12);
  const double spread = MeasureMotionDiversity({Eigen::Matrix3d::Identity(), x, z}).axis_spread_rad;
  EXPECT_GT(spread, 60 * testing::kDegree);
  EXPECT_LT(spread, 120 * testing::kDegree);
}

TEST(HandEyeDegeneracy, RejectsNonFinitePoseNamingTheIndex) {
  std::vector<HandEyeObservation> observations = Observe(GoodPoses());
  observations[3].T_cam_board.translation().x() = std::numeric_limits<double>::quiet_NaN();
  try {
    SolveRobotWorldHandEye(observations);
    FAIL() << "a NaN pose was accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what())
                  .find("observation 3 T_cam_board is not a rigid transform: not finite"),
              std::string::npos)
        << error.what();
  }
}

TEST(HandEyeDegeneracy, RejectsNonRigidPoseNamingTheIndex) {
  std::vector<HandEyeObservation> observations = Observe(GoodPoses());
  observations[4].T_base_flange.linear() *= 1.01;  // a scaled "rotation"
  try {
    SolveRobotWorldHandEye(observations);
    FAIL() << "a scaled pose was accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(
        std::string(error.what()).find("observation 4 T_base_flange is not a rigid transform"),
        std::string::npos)
        << error.what();
  }
  observations = Observe(GoodPoses());
  observations[1].T_base_flange.linear().col(2) *= -1;  // a reflection
  EXPECT_THROW(SolveRobotWorldHandEye(observations), std::invalid_argument);
}

}  // namespace
}  // namespace avc::calibration::hand_eye
