#include "sim/cell/cell_truth.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "sim/cell/perturbation.h"

namespace avc::sim {
namespace {

constexpr double kPi = std::numbers::pi;

// Elementary homogeneous matrices, composed here independently of the kinematics library.
Eigen::Matrix4d RotZ(double angle) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m(0, 0) = std::cos(angle);
  m(0, 1) = -std::sin(angle);
  m(1, 0) = std::sin(angle);
  m(1, 1) = std::cos(angle);
  return m;
}

Eigen::Matrix4d RotX(double angle) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m(1, 1) = std::cos(angle);
  m(1, 2) = -std::sin(angle);
  m(2, 1) = std::sin(angle);
  m(2, 2) = std::cos(angle);
  return m;
}

Eigen::Matrix4d Shift(double x, double y, double z) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<3, 1>(0, 3) << x, y, z;
  return m;
}

// T_table_world by Rodrigues' formula about the line through c along k.
Eigen::Matrix4d TurntableMatrix(const Eigen::Vector3d& k, const Eigen::Vector3d& c, double angle) {
  Eigen::Matrix3d cross;
  cross << 0, -k.z(), k.y(), k.z(), 0, -k.x(), -k.y(), k.x(), 0;
  const Eigen::Matrix3d r = std::cos(angle) * Eigen::Matrix3d::Identity() +
                            std::sin(angle) * cross + (1 - std::cos(angle)) * k * k.transpose();
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<3, 3>(0, 0) = r;
  m.block<3, 1>(0, 3) = c - r * c;
  return m;
}

// T_world_cam = T_world_table * T_table_base * T_base_flange * T_flange_cam, inverted at the end.
Eigen::Matrix4d IndependentCamFromWorld(const CellTruth& cell, const kinematics::JointVector& q,
                                        double angle) {
  Eigen::Matrix4d base_flange = Eigen::Matrix4d::Identity();
  for (int i = 0; i < 6; ++i) {
    base_flange *= RotZ(q[i] + cell.dh.theta_offset[i]) * Shift(0, 0, cell.dh.d[i]) *
                   Shift(cell.dh.a[i], 0, 0) * RotX(cell.dh.alpha[i]);
  }
  const Eigen::Matrix4d table_world =
      TurntableMatrix(cell.turntable_axis_table, cell.turntable_centre_table, angle);
  const Eigen::Matrix4d world_cam = table_world.inverse() * cell.T_base_table.matrix().inverse() *
                                    base_flange * cell.T_flange_cam.matrix();
  return world_cam.inverse();
}

TEST(CellTruth, NominalCellIsValidAndSensible) {
  const CellTruth cell = NominalCell();
  EXPECT_EQ(cell.Validate(), "");
  const Eigen::Vector3d base = cell.T_base_table.inverse().translation();
  EXPECT_GE(base.head<2>().norm(), 0.5);
  EXPECT_LE(base.head<2>().norm(), 0.7);
  EXPECT_EQ(cell.intrinsics.width, 1280);
  EXPECT_EQ(cell.intrinsics.height, 960);
  EXPECT_GE(cell.intrinsics.fx, 1500);
  EXPECT_LE(cell.intrinsics.fx, 2000);
  const double hand_eye_distance = cell.T_flange_cam.translation().norm();
  EXPECT_GE(hand_eye_distance, 0.05);
  EXPECT_LE(hand_eye_distance, 0.15);
}

TEST(CellTruth, ValidateNamesTheBadField) {
  CellTruth cell = NominalCell();
  cell.turntable_axis_table = Eigen::Vector3d(0, 0, 2);
  EXPECT_NE(cell.Validate().find("turntable axis"), std::string::npos);
  cell = NominalCell();
  cell.T_flange_cam.linear()(0, 0) = 1.5;
  EXPECT_NE(cell.Validate().find("T_flange_cam"), std::string::npos);
  cell = NominalCell();
  cell.intrinsics.fx = -1;
  EXPECT_NE(cell.Validate().find("camera"), std::string::npos);
  cell = NominalCell();
  cell.dh.d[2] = std::nan("");
  EXPECT_NE(cell.Validate().find("d[3]"), std::string::npos);
}

TEST(CameraAt, MatchesAnIndependentlyComposedChain) {
  for (uint32_t seed : {0u, 1u, 2u, 3u}) {
    const CellTruth cell = seed == 0 ? NominalCell() : PerturbedCell(seed);
    for (const double angle : {0.0, 0.7, -2.5, kPi}) {
      kinematics::JointVector q;
      q << 0.3 * seed - 0.4, -1.2, 1.4 + 0.1 * seed, -1.7, -1.5, 0.2 - angle;
      const camera::Camera camera = CameraAt(cell, q, angle);
      const Eigen::Matrix4d expected = IndependentCamFromWorld(cell, q, angle);
      EXPECT_LT((camera.T_cam_world.matrix() - expected).cwiseAbs().maxCoeff(), 1e-12)
          << "seed " << seed << " angle " << angle;
      EXPECT_EQ(camera.intrinsics.fx, cell.intrinsics.fx);
      EXPECT_EQ(camera.intrinsics.distortion, cell.intrinsics.distortion);
    }
  }
}

TEST(CameraAt, TurntableRotationMovesTheWorldNotTheCamera) {
  const CellTruth cell = PerturbedCell(8);
  kinematics::JointVector q;
  q << -0.2, -1.4, 1.6, -1.8, -1.5, 0.1;
  const camera::Camera at_zero = CameraAt(cell, q, 0.0);
  const camera::Camera turned = CameraAt(cell, q, 1.1);
  // The camera stays put in the table frame: its world pose is the table pose seen from the
  // turned world.
  const Eigen::Vector3d centre_table = at_zero.Centre();
  EXPECT_LT((TableFromWorld(cell, 1.1) * turned.Centre() - centre_table).norm(), 1e-12);
  // A world point carried by the table projects where its table position projected before.
  const Eigen::Vector3d plant_point(0.05, -0.03, 0.12);
  const auto seen_turned = turned.Project(plant_point);
  const auto seen_fixed = at_zero.Project(TableFromWorld(cell, 1.1) * plant_point);
  ASSERT_TRUE(seen_turned && seen_fixed);
  EXPECT_LT((*seen_turned - *seen_fixed).norm(), 1e-9);
}

TEST(CameraAt, RejectsBadInput) {
  const CellTruth cell = NominalCell();
  kinematics::JointVector q = kinematics::JointVector::Zero();
  EXPECT_THROW(CameraAt(cell, q, std::nan("")), std::invalid_argument);
  q[3] = std::nan("");
  EXPECT_THROW(CameraAt(cell, q, 0.0), std::invalid_argument);
  q[3] = 7.0;  // beyond +-2 pi
  EXPECT_THROW(CameraAt(cell, q, 0.0), std::invalid_argument);
}

TEST(TableFromWorld, RotatesAboutTheTrueAxis) {
  const CellTruth cell = PerturbedCell(4);
  const Eigen::Vector3d& axis = cell.turntable_axis_table;
  const Eigen::Vector3d& centre = cell.turntable_centre_table;
  ASSERT_GT(std::acos(axis.z()), 1e-5) << "the perturbed axis should be tilted";
  EXPECT_TRUE(TableFromWorld(cell, 0.0).isApprox(Eigen::Isometry3d::Identity(), 1e-15));
  const Eigen::Vector3d point(0.12, -0.07, 0.2);
  const Eigen::Vector3d offset0 = point - centre;
  const Eigen::Vector3d radial0 = offset0 - offset0.dot(axis) * axis;
  for (const double angle : {0.3, 1.0, 2.0, -0.8, 3.0}) {
    const Eigen::Vector3d moved = TableFromWorld(cell, angle) * point - centre;
    const Eigen::Vector3d radial = moved - moved.dot(axis) * axis;
    EXPECT_NEAR(moved.dot(axis), offset0.dot(axis), 1e-12);  // stays at its height on the axis
    EXPECT_NEAR(radial.norm(), radial0.norm(), 1e-12);       // and at its distance from it
    // Signed angle about the axis, right-handed.
    const double turned = std::atan2(radial0.cross(radial).dot(axis), radial0.dot(radial));
    EXPECT_NEAR(turned, angle, 1e-12);
  }
  // The axis points themselves do not move.
  const Eigen::Vector3d on_axis = centre + 0.3 * axis;
  EXPECT_LT((TableFromWorld(cell, 1.3) * on_axis - on_axis).norm(), 1e-15);
}

}  // namespace
}  // namespace avc::sim
