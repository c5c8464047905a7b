// Ceres reprojection refinement: exact on noise-free data from a perturbed start, at least as good
// as the closed form under noise, robust to a misdetected corner, and clear about bad input.

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <numbers>
#include <string>

#include "bench/calibration/hand_eye/hand_eye_scenario.h"
#include "core/calibration/hand_eye/core_projection_jet.h"
#include "core/calibration/hand_eye/reprojection_refinement.h"
#include "core/calibration/hand_eye/robot_world_hand_eye.h"
#include "tests/core/calibration/hand_eye/hand_eye_test_util.h"

namespace avc::calibration::hand_eye {
namespace {

using testing::RotationErrorDeg;
using testing::TranslationErrorMm;

bench::HandEyeScenarioOptions NoisyOptions() {
  bench::HandEyeScenarioOptions options;
  options.pixel_sigma_px = 0.5;
  options.robot_rotation_sigma_deg = 0.005;
  options.robot_translation_sigma_mm = 0.05;
  return options;
}

Eigen::Isometry3d Nudge(const Eigen::Isometry3d& pose, double angle, const Eigen::Vector3d& shift) {
  Eigen::Isometry3d nudged = pose;
  nudged.linear() = Eigen::AngleAxisd(angle, Eigen::Vector3d(1, 2, 3).normalized()) * pose.linear();
  nudged.translation() += shift;
  return nudged;
}

double Median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

TEST(HandEyeRefinement, ConvergesExactlyOnNoiseFreeData) {
  const bench::HandEyeScenario scenario = bench::MakeHandEyeScenario({}, 21);
  const Eigen::Isometry3d true_T_board_base = scenario.true_T_base_board.inverse();
  const Eigen::Isometry3d true_T_cam_flange = scenario.true_T_flange_cam.inverse();
  // Start 1 deg and 1 cm away from the truth on both transforms.
  const RefinementResult result = RefineOnReprojection(
      scenario.BoardViews(), scenario.intrinsics,
      Nudge(true_T_board_base, testing::kDegree, Eigen::Vector3d(0.01, 0, -0.01)),
      Nudge(true_T_cam_flange, -testing::kDegree, Eigen::Vector3d(0, 0.01, 0.005)));
  EXPECT_TRUE(result.converged) << result.solver_report;
  EXPECT_GT(result.initial_rms_px, 5.0);
  EXPECT_LT(result.rms_px, 1e-8);
  for (double rms : result.view_rms_px) EXPECT_LT(rms, 1e-8);
  EXPECT_LT(RotationErrorDeg(result.T_board_base, true_T_board_base), 1e-9);
  EXPECT_LT(TranslationErrorMm(result.T_board_base, true_T_board_base), 1e-9);
  EXPECT_LT(RotationErrorDeg(result.T_cam_flange, true_T_cam_flange), 1e-9);
  EXPECT_LT(TranslationErrorMm(result.T_cam_flange, true_T_cam_flange), 1e-9);
}

TEST(HandEyeRefinement, AtLeastAsGoodAsTheClosedFormUnderNoise) {
  std::vector<double> closed_rotation, closed_translation, refined_rotation, refined_translation;
  std::vector<double> closed_world, refined_world;
  for (uint64_t seed = 200; seed < 230; ++seed) {
    const bench::HandEyeScenario scenario = bench::MakeHandEyeScenario(NoisyOptions(), seed);
    const HandEyeSolution closed = SolveRobotWorldHandEye(scenario.Observations());
    const RefinementResult refined = RefineOnReprojection(
        scenario.BoardViews(), scenario.intrinsics, closed.T_board_base, closed.T_cam_flange);
    EXPECT_LE(refined.rms_px, refined.initial_rms_px);
    // 0.5 px per axis is 0.71 px per corner, which cannot be fitted away; robot noise adds a bit.
    EXPECT_GT(refined.rms_px, 0.6);
    EXPECT_LT(refined.rms_px, 1.0);
    closed_rotation.push_back(RotationErrorDeg(closed.T_flange_cam(), scenario.true_T_flange_cam));
    closed_translation.push_back(
        TranslationErrorMm(closed.T_flange_cam(), scenario.true_T_flange_cam));
    closed_world.push_back(TranslationErrorMm(closed.T_base_board(), scenario.true_T_base_board));
    refined_rotation.push_back(
        RotationErrorDeg(refined.T_cam_flange.inverse(), scenario.true_T_flange_cam));
    refined_translation.push_back(
        TranslationErrorMm(refined.T_cam_flange.inverse(), scenario.true_T_flange_cam));
    refined_world.push_back(
        TranslationErrorMm(refined.T_board_base.inverse(), scenario.true_T_base_board));
  }
  EXPECT_LE(Median(refined_rotation), Median(closed_rotation));
  EXPECT_LE(Median(refined_translation), Median(closed_translation));
  EXPECT_LE(Median(refined_world), Median(closed_world));
  // The closed form gives about 0.09 deg / 0.9 mm here (1280x960, fx 1500 px), the refinement
  // about 0.03 deg / 0.2 mm; bounds at ~2x the refined figures.
  EXPECT_LT(Median(refined_rotation), 0.07);
  EXPECT_LT(Median(refined_translation), 0.45);
  EXPECT_LT(Median(refined_translation), 0.5 * Median(closed_translation));
}

// With robot-pose noise alone, taking the reported poses as exact lets their errors steer the
// solution along what the camera measures poorly; the robot-pose corrections with their prior
// remove most of that.
TEST(HandEyeRefinement, RobotPoseCorrectionsAbsorbRobotNoise) {
  bench::HandEyeScenarioOptions options;
  options.robot_rotation_sigma_deg = 0.005;
  options.robot_translation_sigma_mm = 0.05;
  RefinementOptions exact_robot;
  exact_robot.robot_rotation_sigma_deg = 0;
  exact_robot.robot_translation_sigma_mm = 0;
  std::vector<double> corrected, uncorrected;
  for (uint64_t seed = 300; seed < 330; ++seed) {
    const bench::HandEyeScenario scenario = bench::MakeHandEyeScenario(options, seed);
    const HandEyeSolution closed = SolveRobotWorldHandEye(scenario.Observations());
    const RefinementResult with = RefineOnReprojection(scenario.BoardViews(), scenario.intrinsics,
                                                       closed.T_board_base, closed.T_cam_flange);
    const RefinementResult without =
        RefineOnReprojection(scenario.BoardViews(), scenario.intrinsics, closed.T_board_base,
                             closed.T_cam_flange, exact_robot);
    corrected.push_back(RotationErrorDeg(with.T_cam_flange.inverse(), scenario.true_T_flange_cam));
    uncorrected.push_back(
        RotationErrorDeg(without.T_cam_flange.inverse(), scenario.true_T_flange_cam));
    for (double correction : without.view_robot_correction_deg) EXPECT_EQ(correction, 0);
    for (double correction : with.view_robot_correction_mm) EXPECT_LT(correction, 0.5);
  }
  EXPECT_LT(Median(corrected), 0.6 * Median(uncorrected));
}

TEST(HandEyeRefinement, HuberLimitsAMisdetectedCorner) {
  const bench::HandEyeScenario scenario = bench::MakeHandEyeScenario({}, 31);
  std::vector<BoardView> views = scenario.BoardViews();
  views[2].pixels[7] += Eigen::Vector2d(60, -40);
  const Eigen::Isometry3d true_T_cam_flange = scenario.true_T_flange_cam.inverse();
  const Eigen::Isometry3d true_T_board_base = scenario.true_T_base_board.inverse();
  RefinementOptions plain;
  plain.huber_px = 0;
  const RefinementResult robust =
      RefineOnReprojection(views, scenario.intrinsics, true_T_board_base, true_T_cam_flange);
  const RefinementResult squared =
      RefineOnReprojection(views, scenario.intrinsics, true_T_board_base, true_T_cam_flange, plain);
  const double robust_error = TranslationErrorMm(robust.T_cam_flange, true_T_cam_flange);
  const double squared_error = TranslationErrorMm(squared.T_cam_flange, true_T_cam_flange);
  EXPECT_LT(robust_error, 0.5 * squared_error);
  // The bad view stands out in the per-view report.
  EXPECT_EQ(std::max_element(robust.view_rms_px.begin(), robust.view_rms_px.end()) -
                robust.view_rms_px.begin(),
            2);
}

TEST(HandEyeRefinement, UsesTheCameraModelOfCoreCamera) {
  const camera::Intrinsics intrinsics = bench::MakeHandEyeScenario({}, 1).intrinsics;
  using Jet = ceres::Jet<double, 2>;
  const Eigen::Vector2d point(0.21, -0.17);
  const Eigen::Matrix<Jet, 2, 1> jet(Jet(point.x(), 0), Jet(point.y(), 1));
  const Eigen::Matrix<Jet, 2, 1> distorted = DistortForCeres(intrinsics, jet);
  const Eigen::Vector2d expected = intrinsics.Distort(point);
  EXPECT_EQ(distorted.x().a, expected.x());
  EXPECT_EQ(distorted.y().a, expected.y());
  // The derivative against a coarse independent difference.
  const double h = 1e-4;
  const Eigen::Vector2d dx = (intrinsics.Distort(point + Eigen::Vector2d(h, 0)) -
                              intrinsics.Distort(point - Eigen::Vector2d(h, 0))) /
                             (2 * h);
  EXPECT_NEAR(distorted.x().v(0), dx.x(), 1e-7);
  EXPECT_NEAR(distorted.y().v(0), dx.y(), 1e-7);
  EXPECT_GT(std::abs(distorted.x().v(0) - 1), 1e-3);  // the distortion is not negligible here
}

// The message of the std::invalid_argument the refinement raises ("" if none).
std::string Rejection(const std::vector<BoardView>& views, const camera::Intrinsics& intrinsics,
                      const Eigen::Isometry3d& T_board_base,
                      const Eigen::Isometry3d& T_cam_flange) {
  try {
    RefineOnReprojection(views, intrinsics, T_board_base, T_cam_flange);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

TEST(HandEyeRefinement, RejectsBadInputWithTheReason) {
  const bench::HandEyeScenario scenario = bench::MakeHandEyeScenario({}, 41);
  const Eigen::Isometry3d X = scenario.true_T_base_board.inverse();
  const Eigen::Isometry3d Z = scenario.true_T_flange_cam.inverse();
  const std::vector<BoardView> good = scenario.BoardViews();
  EXPECT_EQ(Rejection(good, scenario.intrinsics, X, Z), "");
  EXPECT_NE(Rejection({}, scenario.intrinsics, X, Z).find("no views"), std::string::npos);

  std::vector<BoardView> views = good;
  views[1].pixels.pop_back();
  EXPECT_NE(Rejection(views, scenario.intrinsics, X, Z).find("view 1 has 54 board points and 53"),
            std::string::npos);
  views = good;
  views[2].pixels[5].y() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(Rejection(views, scenario.intrinsics, X, Z).find("view 2 corner 5 is not finite"),
            std::string::npos);
  views = good;
  views[3].T_base_flange.linear() *= 2;
  EXPECT_NE(
      Rejection(views, scenario.intrinsics, X, Z).find("view 3 pose is not a rigid transform"),
      std::string::npos);
  RefinementOptions half_prior;
  half_prior.robot_rotation_sigma_deg = 0;
  EXPECT_THROW(RefineOnReprojection(good, scenario.intrinsics, X, Z, half_prior),
               std::invalid_argument);
  camera::Intrinsics bad = scenario.intrinsics;
  bad.fx = -1;
  EXPECT_NE(Rejection(good, bad, X, Z).find("focal lengths"), std::string::npos);
  // A hand-eye that turns the camera around: the board is behind it.
  const Eigen::Isometry3d flipped =
      Eigen::Isometry3d(Eigen::AngleAxisd(std::numbers::pi, Eigen::Vector3d::UnitX())) * Z;
  EXPECT_NE(Rejection(good, scenario.intrinsics, X, flipped).find("behind the camera"),
            std::string::npos);
}

}  // namespace
}  // namespace avc::calibration::hand_eye
