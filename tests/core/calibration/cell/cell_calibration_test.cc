// The calibrated camera chain: with the simulated cell's true parameters it reproduces the
// simulator's cameras for every arm pose and table angle (up to the one fixed choice of world
// frame); calibration.yaml round-trips byte for byte and names the line of every problem.

#include "core/calibration/cell/cell_calibration.h"

#include <gtest/gtest.h>

#include <numbers>

#include "core/calibration/cell/calibration_yaml.h"
#include "core/calibration/turntable/turntable_views.h"
#include "sim/cell/cell_truth.h"
#include "sim/cell/perturbation.h"
#include "tests/support/test_support.h"

namespace avc::calibration {
namespace {

// The calibration a perfect calibrator would find for the simulated cell.
CellCalibration FromTruth(const sim::CellTruth& truth) {
  CellCalibration calibration;
  calibration.intrinsics = truth.intrinsics;
  calibration.T_flange_cam = truth.T_flange_cam;
  calibration.dh = truth.dh;
  const Eigen::Vector3d axis_base = truth.T_base_table.linear() * truth.turntable_axis_table;
  const Eigen::Vector3d centre_base = truth.T_base_table * truth.turntable_centre_table;
  // Any point off the axis fixes the table frame's x direction.
  calibration.T_base_table =
      TableFrame(TurntableAxis{axis_base, centre_base},
                 centre_base + truth.T_base_table.linear() * Eigen::Vector3d(0.1, 0.02, 0));
  return calibration;
}

kinematics::JointVector Joints(double a, double b, double c, double d, double e, double f) {
  return (kinematics::JointVector() << a, b, c, d, e, f).finished();
}

TEST(CellCalibration, ReproducesTheSimulatorsCamerasForAnyArmPoseAndTableAngle) {
  const sim::CellTruth truth = sim::PerturbedCell(7);
  const CellCalibration calibration = FromTruth(truth);
  ASSERT_TRUE(calibration.Validate().empty()) << calibration.Validate();
  // The calibrated world frame differs from the simulator's by one fixed rigid transform G
  // (origin and x direction are choices): T_cam_world_sim = T_cam_world_cal * G everywhere.
  const kinematics::JointVector q0 = Joints(0.3, -1.2, 1.4, -1.8, -1.5, 0.2);
  const Eigen::Isometry3d G = calibration.CameraAtJoints(q0, 0).T_cam_world.inverse() *
                              sim::CameraAt(truth, q0, 0).T_cam_world;
  for (const auto& [q, angle] : std::vector<std::pair<kinematics::JointVector, double>>{
           {Joints(0.1, -1.0, 1.2, -1.6, -1.4, 0.5), 0.7},
           {Joints(-0.4, -1.5, 1.7, -2.0, -1.6, -0.3), -2.1},
           {q0, std::numbers::pi}}) {
    const Eigen::Isometry3d expected = sim::CameraAt(truth, q, angle).T_cam_world;
    const Eigen::Isometry3d got = calibration.CameraAtJoints(q, angle).T_cam_world * G;
    EXPECT_LT((got.matrix() - expected.matrix()).cwiseAbs().maxCoeff(), 1e-12) << angle;
  }
  // G (simulator world to calibrated world) maps the true axis onto the table's z axis.
  EXPECT_LT((G.linear() * truth.turntable_axis_table - Eigen::Vector3d::UnitZ()).norm(), 1e-12);
}

TEST(CellCalibration, RefusesNonFiniteQueriesAndNonRigidTransforms) {
  CellCalibration calibration = FromTruth(sim::NominalCell());
  EXPECT_THROW(calibration.CameraAt(Eigen::Isometry3d::Identity(), std::nan("")),
               std::invalid_argument);
  EXPECT_THROW(calibration.CameraAtJoints(Joints(0, 0, 0, 0, 0, 100), 0), std::invalid_argument);
  calibration.T_flange_cam.linear() *= 2;
  EXPECT_EQ(calibration.Validate(),
            "T_flange_cam is not a rigid transform: its rotation block has |R R^T - I| = 5.2");
}

TEST(CalibrationYaml, RoundTripsByteForByte) {
  CellCalibration calibration = FromTruth(sim::PerturbedCell(3));
  calibration.note = "simulated cell, seed 3";
  calibration.residuals.view_names = {"view_0000", "view_0001"};
  calibration.residuals.view_rms_px = {0.123456789012345, 0.2};
  calibration.residuals.rejected = {"view_0002: board not found"};
  calibration.residuals.intrinsics_rms_px = 0.17;
  calibration.residuals.turntable_angles = 10;
  const std::string text = CalibrationToYaml(calibration);
  const CellCalibration back = CalibrationFromYaml(text, "memory");
  EXPECT_EQ(CalibrationToYaml(back), text);
  EXPECT_EQ(back.T_flange_cam.matrix(), calibration.T_flange_cam.matrix());
  EXPECT_EQ(back.dh.a, calibration.dh.a);
  EXPECT_EQ(back.residuals.view_rms_px, calibration.residuals.view_rms_px);
  EXPECT_EQ(back.residuals.rejected, calibration.residuals.rejected);

  testing::TempDir dir("avc-calibration-yaml");
  SaveCalibration(calibration, dir / "calibration.yaml");
  EXPECT_EQ(testing::ReadFile(dir / "calibration.yaml"), text);
  EXPECT_EQ(CalibrationToYaml(LoadCalibration(dir / "calibration.yaml")), text);
}

TEST(CalibrationYaml, NamesTheLineAndFieldOfEveryProblem) {
  const std::string good = CalibrationToYaml(FromTruth(sim::NominalCell()));
  const auto error_of = [](const std::string& text) {
    try {
      CalibrationFromYaml(text, "cal.yaml");
    } catch (const std::runtime_error& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  std::string wrong_version = good;
  wrong_version.replace(wrong_version.find("format_version: 1"), 17, "format_version: 9");
  EXPECT_NE(error_of(wrong_version).find("format_version 9 is not supported"), std::string::npos);
  std::string short_matrix = good;
  const size_t at = short_matrix.find("\nT_flange_cam:");
  short_matrix.replace(short_matrix.find('[', at), 1, "[7, ");
  EXPECT_NE(error_of(short_matrix).find("'T_flange_cam' must be a list of 16 numbers"),
            std::string::npos)
      << error_of(short_matrix);
  EXPECT_EQ(error_of(short_matrix).rfind("cal.yaml:", 0), 0u);
  std::string no_camera = good;
  no_camera.replace(no_camera.find("camera:"), 7, "kamera:");
  EXPECT_NE(error_of(no_camera).find("missing 'camera'"), std::string::npos);
  EXPECT_NE(error_of("[1, 2").find("not valid YAML"), std::string::npos);
  EXPECT_THROW(LoadCalibration("/nonexistent/calibration.yaml"), std::runtime_error);
}

// Found by fuzz/calibration_yaml_fuzzer: a width of 8.2e9 was cast to int (undefined behaviour).
TEST(CalibrationYaml, RefusesSizesThatAreNotWholeNumbersOfPixels) {
  const std::string good = CalibrationToYaml(FromTruth(sim::NominalCell()));
  const size_t at = good.find("width: ");
  ASSERT_NE(at, std::string::npos);
  const size_t end = good.find('\n', at);
  for (const std::string width : {"8.2e9", "-1e300", "640.5", ".nan"}) {
    std::string text = good;
    text.replace(at, end - at, "width: " + width);
    try {
      CalibrationFromYaml(text, "cal.yaml");
      ADD_FAILURE() << "width " << width << " was accepted";
    } catch (const std::runtime_error& error) {
      EXPECT_EQ(std::string(error.what()).rfind("cal.yaml:", 0), 0u) << error.what();
      EXPECT_NE(std::string(error.what()).find("'width' must be a whole number"), std::string::npos)
          << error.what();
    }
  }
}

}  // namespace
}  // namespace avc::calibration
