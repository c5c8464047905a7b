#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "sim/cell/perturbation.h"
#include "sim/cell/view_selection.h"

namespace avc::sim {
namespace {

constexpr double kDegree = std::numbers::pi / 180;

kinematics::JointVector Home() {
  kinematics::JointVector q;
  q << 0, -std::numbers::pi / 2, std::numbers::pi / 2, -std::numbers::pi / 2, -std::numbers::pi / 2,
      0;
  return q;
}

// The paper's initial views: three elevations; here also a spread of azimuths and distances.
TEST(JointsLookingAt, CameraLandsOnTheRequestedViewExactly) {
  const Eigen::Vector3d target(0.0, 0.0, 0.15);
  int views = 0;
  for (const CellTruth& cell : {NominalCell(), PerturbedCell(7), PerturbedCell(21)}) {
    const double robot_azimuth = RobotAzimuth(cell);
    for (const double elevation : {20.0, 40.0, 60.0}) {
      for (const double azimuth_offset : {-60.0, -30.0, 30.0, 60.0}) {
        for (const double distance : {0.45, 0.6}) {
          const Eigen::Vector3d centre = ViewpointOnSphere(
              target, distance, elevation * kDegree, robot_azimuth + azimuth_offset * kDegree);
          const std::optional<kinematics::JointVector> q =
              JointsLookingAt(cell, centre, target, Home());
          ASSERT_TRUE(q.has_value()) << "elevation " << elevation << " azimuth " << azimuth_offset
                                     << " distance " << distance;
          ++views;
          ASSERT_TRUE(kinematics::WithinJointLimits(*q));
          const camera::Camera camera = CameraAt(cell, *q, 0.0);
          EXPECT_LT((camera.Centre() - centre).norm(), 1e-6);
          const std::optional<Eigen::Vector2d> pixel = camera.Project(target);
          ASSERT_TRUE(pixel.has_value());
          EXPECT_LT((*pixel - Eigen::Vector2d(cell.intrinsics.cx, cell.intrinsics.cy)).norm(),
                    1e-3);
          // Upright image: camera x horizontal, camera y pointing down.
          const Eigen::Matrix3d R_table_cam = camera.T_cam_world.linear().transpose();
          EXPECT_NEAR(R_table_cam(2, 0), 0.0, 1e-9);
          EXPECT_LT(R_table_cam(2, 1), 0.0);
        }
      }
    }
  }
  EXPECT_EQ(views, 72);
}

TEST(JointsLookingAt, PicksTheBranchNearestTheCurrentJoints) {
  const CellTruth cell = PerturbedCell(7);
  const Eigen::Vector3d target(0.0, 0.0, 0.15);
  const Eigen::Vector3d centre =
      ViewpointOnSphere(target, 0.55, 35 * kDegree, RobotAzimuth(cell) + 0.5);
  const std::optional<kinematics::JointVector> q = JointsLookingAt(cell, centre, target, Home());
  ASSERT_TRUE(q.has_value());
  // Elbow up like the home pose, and within a turn of it on every joint.
  EXPECT_GT((*q)[2], 0.0);
  EXPECT_LT((*q - Home()).cwiseAbs().maxCoeff(), std::numbers::pi);
  // Asking again from there returns the same joints: a view already reached needs no motion.
  const std::optional<kinematics::JointVector> again = JointsLookingAt(cell, centre, target, *q);
  ASSERT_TRUE(again.has_value());
  EXPECT_LT((*again - *q).cwiseAbs().maxCoeff(), 1e-9);
  // Starting one turn around on joint 6 keeps that turn.
  kinematics::JointVector turned = *q;
  turned[5] += turned[5] > 0 ? -2 * std::numbers::pi : 2 * std::numbers::pi;
  const std::optional<kinematics::JointVector> kept = JointsLookingAt(cell, centre, target, turned);
  ASSERT_TRUE(kept.has_value());
  EXPECT_NEAR((*kept)[5], turned[5], 1e-9);
}

TEST(JointsLookingAt, TurntableAngleOnlyMovesTheWorld) {
  const CellTruth cell = PerturbedCell(11);
  const Eigen::Vector3d target(0.0, 0.0, 0.15);
  const Eigen::Vector3d centre =
      ViewpointOnSphere(target, 0.5, 45 * kDegree, RobotAzimuth(cell) - 0.4);
  const std::optional<kinematics::JointVector> q = JointsLookingAt(cell, centre, target, Home());
  ASSERT_TRUE(q.has_value());
  for (int k = 0; k < 10; ++k) {  // the paper's 10 turntable positions
    const double angle = k * 36 * kDegree;
    const camera::Camera camera = CameraAt(cell, *q, angle);
    EXPECT_LT((TableFromWorld(cell, angle) * camera.Centre() - centre).norm(), 1e-6);
  }
}

TEST(JointsLookingAt, NominalModelMissesTheTrueCellByMillimetres) {
  // Planning with the nominal cell and moving the true arm puts the camera off by the cell's
  // perturbations: the reason the calibrator exists.
  const CellTruth truth = PerturbedCell(7);
  const Eigen::Vector3d target(0.0, 0.0, 0.15);
  const Eigen::Vector3d centre =
      ViewpointOnSphere(target, 0.5, 40 * kDegree, RobotAzimuth(truth) + 0.3);
  const std::optional<kinematics::JointVector> q =
      JointsLookingAt(NominalCell(), centre, target, Home());
  ASSERT_TRUE(q.has_value());
  const double miss = (CameraAt(truth, *q, 0.0).Centre() - centre).norm();
  EXPECT_GT(miss, 1e-3);
  EXPECT_LT(miss, 0.05);
}

TEST(JointsLookingAt, UnreachableViewsGiveNullopt) {
  const CellTruth cell = NominalCell();
  const Eigen::Vector3d target(0.0, 0.0, 0.15);
  // Two metres away on the far side of the turntable.
  EXPECT_FALSE(JointsLookingAt(cell, Eigen::Vector3d(2.0, 0.0, 0.5), target, Home()).has_value());
  // Straight above at 1.5 m: beyond the arm's reach.
  EXPECT_FALSE(JointsLookingAt(cell, Eigen::Vector3d(0.0, 0.0, 1.65), target, Home()).has_value());
}

TEST(JointsLookingAt, RejectsBadInput) {
  const CellTruth cell = NominalCell();
  const Eigen::Vector3d target(0.0, 0.0, 0.15);
  EXPECT_THROW(JointsLookingAt(cell, target, target, Home()), std::invalid_argument);
  EXPECT_THROW(JointsLookingAt(cell, Eigen::Vector3d(std::nan(""), 0, 0), target, Home()),
               std::invalid_argument);
  EXPECT_THROW(JointsLookingAt(cell, Eigen::Vector3d(0.3, 0, 0.4), target,
                               kinematics::JointVector::Constant(std::nan(""))),
               std::invalid_argument);
  CellTruth broken = cell;
  broken.intrinsics.width = 0;
  EXPECT_THROW(JointsLookingAt(broken, Eigen::Vector3d(0.3, 0, 0.4), target, Home()),
               std::invalid_argument);
}

TEST(LookAtPose, StraightDownViewHasTheRobotAtTheTopOfTheImage) {
  const Eigen::Vector3d robot(-0.55, 0.0, 0.2);
  const Eigen::Isometry3d pose =
      LookAtPose(Eigen::Vector3d(0, 0, 0.7), Eigen::Vector3d(0, 0, 0.1), robot);
  const Eigen::Matrix3d axes = pose.linear();
  EXPECT_LT((axes.col(2) - Eigen::Vector3d(0, 0, -1)).norm(), 1e-12);  // looking down
  EXPECT_LT((axes.col(1) - Eigen::Vector3d(1, 0, 0)).norm(), 1e-12);  // image down: away from robot
  EXPECT_NEAR(axes.determinant(), 1.0, 1e-12);
}

TEST(ViewpointOnSphere, PlacesThePointAtDistanceAndAngles) {
  const Eigen::Vector3d target(0.1, -0.2, 0.15);
  const Eigen::Vector3d point = ViewpointOnSphere(target, 0.6, 30 * kDegree, 120 * kDegree);
  const Eigen::Vector3d offset = point - target;
  EXPECT_NEAR(offset.norm(), 0.6, 1e-12);
  EXPECT_NEAR(std::asin(offset.z() / 0.6), 30 * kDegree, 1e-12);
  EXPECT_NEAR(std::atan2(offset.y(), offset.x()), 120 * kDegree, 1e-12);
  EXPECT_NEAR(RobotAzimuth(NominalCell()), std::numbers::pi, 1e-12);
}

}  // namespace
}  // namespace avc::sim
