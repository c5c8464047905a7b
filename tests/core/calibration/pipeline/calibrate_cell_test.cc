// The calibration solve offline, on a dataset rendered in-process from a perturbed simulated
// cell (the same poses `avc calibrate collect` plans, images of the simulated chessboard, flange
// poses through the TRUE kinematics as the controller reports them): the calibration recovers the
// true camera, hand-eye and turntable, so camera poses at unseen arm poses and table angles match
// the truth; bad datasets are refused with the shot and the problem named. The documented
// command line, `avc calibrate solve FOLDER`, parses and solves the same dataset.

#include "core/calibration/pipeline/calibrate_cell.h"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <opencv2/core/persistence.hpp>
#include <opencv2/imgcodecs.hpp>
#include <random>

#include "core/calibration/cell/calibration_yaml.h"
#include "core/calibration/pipeline/intrinsics_file.h"
#include "core/kinematics/forward_kinematics.h"
#include "core/launch/child_process.h"
#include "core/util/ordered_draws.h"
#include "services/calibrator/calibration_plan.h"
#include "sim/cell/perturbation.h"
#include "sim/cell/view_selection.h"
#include "sim/render/renderer.h"
#include "sim/scene/chessboard_scene.h"
#include "tests/support/test_support.h"

namespace avc::calibration {
namespace {

namespace fs = std::filesystem;
constexpr double kDeg = std::numbers::pi / 180;

struct RenderedDataset {
  sim::CellTruth truth;
  sim::ChessboardSpec board;
  CalibrationDataset dataset;
};

// Renders what the collector would capture in the perturbed cell.
RenderedDataset Render(const fs::path& folder) {
  RenderedDataset out;
  out.truth = sim::PerturbedCell(5);
  const sim::Scene scene = sim::ChessboardScene(out.board);
  sim::RenderOptions render;
  render.samples_per_pixel_axis = 4;
  render.background.kind = sim::Background::Kind::kPlain;
  kinematics::JointVector start;
  start << 0, -std::numbers::pi / 2, std::numbers::pi / 2, -std::numbers::pi / 2,
      -std::numbers::pi / 2, 0;
  calibrator::CalibrationPlanOptions plan_options;
  plan_options.hand_eye_poses = 12;
  const calibrator::CalibrationPlan plan =
      calibrator::PlanCalibration(sim::NominalCell(), out.board, start, plan_options);
  fs::create_directories(folder / "images");
  out.dataset.folder = folder;
  out.dataset.board = {out.board.inner_cols, out.board.inner_rows, out.board.square_m};
  sim::Renderer renderer;
  const auto shoot = [&](const std::string& name, const kinematics::JointVector& q, double angle,
                         ShotPurpose purpose) {
    sim::RenderResult result;
    renderer.Render(scene, sim::CameraAt(out.truth, q, angle), render, &result);
    const std::string image = "images/" + name + ".png";
    EXPECT_TRUE(cv::imwrite((folder / image).string(), result.color));
    out.dataset.shots.push_back(
        {image, purpose, angle, kinematics::ForwardKinematics(out.truth.dh, q)});
  };
  for (size_t i = 0; i < plan.hand_eye.size(); ++i) {
    shoot("he_" + std::to_string(i), plan.hand_eye[i], 0, ShotPurpose::kHandEye);
  }
  for (size_t k = 0; k < plan.table_angles.size(); ++k) {
    shoot("tt_" + std::to_string(k), plan.turntable_pose, plan.table_angles[k],
          ShotPurpose::kTurntable);
  }
  SaveCalibrationDataset(out.dataset);
  return out;
}

TEST(CalibrateCell, RecoversTheSimulatedCellAndPredictsCamerasAtUnseenPoses) {
  testing::TempDir dir("avc-calibrate-cell");
  const RenderedDataset rendered = Render(dir.path());
  const CalibrationDataset dataset = LoadCalibrationDataset(dir.path());
  ASSERT_EQ(dataset.shots.size(), 22u);
  CalibrateOptions options;
  options.dh = rendered.truth.dh;
  CalibrationDetails details;
  const CellCalibration calibration = CalibrateCell(dataset, options, &details);
  EXPECT_TRUE(calibration.residuals.rejected.empty());
  EXPECT_EQ(details.hand_eye_views, 12);
  EXPECT_EQ(details.turntable_views, 10);
  EXPECT_LT(calibration.residuals.hand_eye_rms_px, 0.3);
  // The simulated arm's poses are as consistent as the refinement's prior assumes: the refined
  // hand-eye predicts held-out poses better than the closed form, and is kept; both are
  // recorded, in calibration.yaml too.
  const CalibrationResiduals& r = calibration.residuals;
  EXPECT_EQ(r.hand_eye_method, "refined");
  EXPECT_EQ(r.alternative_method, "closed form");
  EXPECT_GT(r.hand_eye_loo_rotation_deg, 0);
  EXPECT_LT(r.hand_eye_loo_rotation_deg, r.alternative_loo_rotation_deg);
  EXPECT_LT(r.hand_eye_loo_rotation_deg, 0.02);
  EXPECT_LT(r.hand_eye_loo_translation_mm, 0.2);
  SaveCalibration(calibration, dir / "calibration.yaml");
  const CalibrationResiduals read = LoadCalibration(dir / "calibration.yaml").residuals;
  EXPECT_EQ(read.hand_eye_method, "refined");
  EXPECT_EQ(read.alternative_loo_translation_mm, r.alternative_loo_translation_mm);

  const camera::Intrinsics& k = calibration.intrinsics;
  const camera::Intrinsics& t = rendered.truth.intrinsics;
  EXPECT_NEAR(k.fx, t.fx, 1.5);  // 22 views of one small board: about 0.1 % in focal length
  EXPECT_NEAR(k.fy, t.fy, 1.5);
  EXPECT_NEAR(k.cx, t.cx, 1.0);
  EXPECT_NEAR(k.cy, t.cy, 1.0);
  EXPECT_LT(
      (calibration.T_flange_cam.translation() - rendered.truth.T_flange_cam.translation()).norm(),
      0.5e-3);

  // Unseen arm poses and table angles: the calibrated camera is where the simulator's is, once
  // both world frames are tied to the board.
  const Eigen::Isometry3d T_cal_sim =
      calibration.T_table_board * rendered.board.T_world_board.inverse();
  const sim::CellTruth nominal = sim::NominalCell();
  std::vector<double> centre_errors, rotation_errors;
  for (const double elevation : {20.0, 30.0}) {
    for (const double angle : {0.3, 2.0, 4.4}) {
      kinematics::JointVector current;
      current << 0, -1.5, 1.5, -1.5, -1.5, 0;
      const auto view = sim::FirstReachableView(nominal, {0, 0, 0.1}, 0.55, elevation * kDeg,
                                                sim::RobotAzimuth(nominal), current);
      ASSERT_TRUE(view.has_value());
      const Eigen::Isometry3d truth = sim::CameraAt(rendered.truth, view->q, angle).T_cam_world;
      const Eigen::Isometry3d estimate =
          calibration.CameraAt(kinematics::ForwardKinematics(rendered.truth.dh, view->q), angle)
              .T_cam_world *
          T_cal_sim;
      centre_errors.push_back(
          (estimate.inverse().translation() - truth.inverse().translation()).norm());
      rotation_errors.push_back(
          Eigen::AngleAxisd(estimate.linear().transpose() * truth.linear()).angle() / kDeg);
    }
  }
  std::sort(centre_errors.begin(), centre_errors.end());
  std::sort(rotation_errors.begin(), rotation_errors.end());
  // The issue's end-to-end figures: centres within 0.5 mm and 0.05 deg (median); no view far off.
  EXPECT_LT(centre_errors[centre_errors.size() / 2], 0.5e-3);
  EXPECT_LT(rotation_errors[rotation_errors.size() / 2], 0.05);
  EXPECT_LT(centre_errors.back(), 1e-3);
  EXPECT_LT(rotation_errors.back(), 0.1);
}

// `avc calibrate solve FOLDER` once read "solve" as the parent's FOLDER and failed with "no
// command named 'FOLDER'"; errors were prefixed "avc solve:".
TEST(CalibrateCell, TheDocumentedCommandLineSolvesADataset) {
  testing::TempDir dir("avc-calibrate-cli");
  const fs::path folder = dir / "dataset";
  const RenderedDataset rendered = Render(folder);
  const auto run = [&](const std::vector<std::string>& args, const fs::path& log) {
    std::vector<std::string> argv = {testing::Executable("avc").string(), "calibrate"};
    argv.insert(argv.end(), args.begin(), args.end());
    launch::ChildProcess child = launch::ChildProcess::Spawn({argv, {}, "", log.string()});
    const std::optional<int> status = child.WaitFor(std::chrono::milliseconds(60000));
    return status && WIFEXITED(*status) ? WEXITSTATUS(*status) : -1;
  };
  ASSERT_EQ(run({"solve", folder.string()}, dir / "solve.log"), 0)
      << testing::ReadFile(dir / "solve.log");
  EXPECT_NE(testing::ReadFile(dir / "solve.log").find("hand-eye: 12 poses"), std::string::npos)
      << testing::ReadFile(dir / "solve.log");
  const CellCalibration solved = LoadCalibration(folder / "calibration.yaml");
  EXPECT_NEAR(solved.intrinsics.fx, rendered.truth.intrinsics.fx, 1.5);
  EXPECT_LT((solved.T_flange_cam.translation() - rendered.truth.T_flange_cam.translation()).norm(),
            0.5e-3);

  fs::create_directories(dir / "empty");
  EXPECT_EQ(run({"solve", (dir / "empty").string()}, dir / "empty.log"), 1);
  EXPECT_EQ(testing::ReadFile(dir / "empty.log").rfind("avc calibrate solve: ", 0), 0u)
      << testing::ReadFile(dir / "empty.log");
  EXPECT_EQ(run({}, dir / "nothing.log"), 1);
  EXPECT_NE(testing::ReadFile(dir / "nothing.log").find("give the dataset FOLDER"),
            std::string::npos)
      << testing::ReadFile(dir / "nothing.log");
}

// A robot without our turntable: hand-eye shots alone (one written without a table angle, which
// means nothing there) solve intrinsics, hand-eye and robot-world, and the calibration says the
// turntable is not calibrated, in memory and in calibration.yaml.
TEST(CalibrateCell, HandEyeShotsAloneGiveAHandEyeOnlyCalibration) {
  testing::TempDir dir("avc-calibrate-hand-eye");
  RenderedDataset rendered = Render(dir.path());
  std::erase_if(rendered.dataset.shots, [](const CalibrationShot& shot) {
    return shot.purpose == ShotPurpose::kTurntable;
  });
  SaveCalibrationDataset(rendered.dataset);
  nlohmann::json doc = nlohmann::json::parse(testing::ReadFile(dir / "dataset.json"));
  doc["shots"][0].erase("table_angle");
  testing::WriteFile(dir / "dataset.json", doc.dump());
  const CalibrationDataset dataset = LoadCalibrationDataset(dir.path());
  ASSERT_EQ(dataset.shots.size(), 12u);

  CalibrateOptions options;
  options.dh = rendered.truth.dh;
  CalibrationDetails details;
  const CellCalibration calibration = CalibrateCell(dataset, options, &details);
  EXPECT_FALSE(calibration.turntable_calibrated);
  EXPECT_EQ(details.turntable_views, 0);
  EXPECT_NE(calibration.note.find("turntable not calibrated"), std::string::npos);
  EXPECT_LT(
      (calibration.T_flange_cam.translation() - rendered.truth.T_flange_cam.translation()).norm(),
      0.5e-3);
  // The board's pose in the base frame (robot-world) stands where the table frame would be.
  const Eigen::Isometry3d T_base_board = rendered.truth.T_base_table * rendered.board.T_world_board;
  EXPECT_LT((calibration.T_base_table.translation() - T_base_board.translation()).norm(), 1e-3);

  SaveCalibration(calibration, dir / "calibration.yaml");
  EXPECT_NE(testing::ReadFile(dir / "calibration.yaml").find("turntable_calibrated: false"),
            std::string::npos);
  EXPECT_FALSE(LoadCalibration(dir / "calibration.yaml").turntable_calibrated);
}

// Known intrinsics (here the truth, from an OpenCV file without the image size) are kept as
// they are, and the hand-eye is solved with them; through the CLI's --intrinsics too.
TEST(CalibrateCell, KnownIntrinsicsAreKeptAndUsed) {
  testing::TempDir dir("avc-calibrate-known");
  const RenderedDataset rendered = Render(dir / "dataset");
  const camera::Intrinsics& truth = rendered.truth.intrinsics;
  {
    cv::FileStorage file((dir / "camera.yaml").string(), cv::FileStorage::WRITE);
    file << "camera_matrix"
         << cv::Mat(cv::Matx33d(truth.fx, 0, truth.cx, 0, truth.fy, truth.cy, 0, 0, 1));
    file << "distortion_coefficients"
         << cv::Mat(std::vector<double>(truth.distortion.begin(), truth.distortion.end()));
  }
  CalibrateOptions options;
  options.dh = rendered.truth.dh;
  options.intrinsics.known = ReadIntrinsicsFile(dir / "camera.yaml");
  EXPECT_EQ(options.intrinsics.known->width, 0) << "the file gives no size";
  const CellCalibration calibration =
      CalibrateCell(LoadCalibrationDataset(dir / "dataset"), options);
  EXPECT_EQ(calibration.intrinsics.fx, truth.fx);
  EXPECT_EQ(calibration.intrinsics.distortion, truth.distortion);
  EXPECT_EQ(calibration.intrinsics.width, truth.width);
  EXPECT_LT(
      (calibration.T_flange_cam.translation() - rendered.truth.T_flange_cam.translation()).norm(),
      0.5e-3);
  EXPECT_LT(calibration.residuals.hand_eye_rms_px, 0.3);

  // Another camera's size is refused, naming both.
  camera::Intrinsics other = truth;
  other.width *= 2;
  options.intrinsics.known = other;
  try {
    CalibrateCell(LoadCalibrationDataset(dir / "dataset"), options);
    ADD_FAILURE() << "intrinsics of another image size must be refused";
  } catch (const std::exception& error) {
    EXPECT_NE(std::string(error.what()).find("the given intrinsics are for"), std::string::npos)
        << error.what();
  }

  // The CLI: our own calibration.yaml as the intrinsics file.
  SaveCalibration(calibration, dir / "known.yaml");
  launch::ChildProcess solve = launch::ChildProcess::Spawn(
      {{testing::Executable("avc").string(), "calibrate", "solve", (dir / "dataset").string(),
        "--intrinsics", (dir / "known.yaml").string(), "-o", (dir / "solved.yaml").string()},
       {},
       "",
       (dir / "solve.log").string()});
  const std::optional<int> status = solve.WaitFor(std::chrono::milliseconds(60000));
  ASSERT_TRUE(status && WIFEXITED(*status) && WEXITSTATUS(*status) == 0)
      << testing::ReadFile(dir / "solve.log");
  EXPECT_EQ(LoadCalibration(dir / "solved.yaml").intrinsics.fx, truth.fx);
}

// An arm whose reported poses are ten times less consistent than a UR5's (0.05 deg / 0.5 mm of
// noise on each hand-eye pose): the refinement with the UR5's prior would bend the camera to fit
// them; the kept hand-eye predicts left-out poses at least as well as the runner-up.
TEST(CalibrateCell, ANoisierArmKeepsTheHandEyeThatPredictsLeftOutPoses) {
  testing::TempDir dir("avc-calibrate-noisy-arm");
  RenderedDataset rendered = Render(dir.path());
  std::mt19937 random(7);
  std::normal_distribution<double> rotation_rad(0, 0.05 * kDeg), translation_m(0, 0.5e-3);
  for (CalibrationShot& shot : rendered.dataset.shots) {
    if (shot.purpose != ShotPurpose::kHandEye) continue;
    const Eigen::Vector3d w =
        util::DrawVector3<Eigen::Vector3d>([&] { return rotation_rad(random); });
    shot.T_base_flange.linear() = Eigen::AngleAxisd(w.norm(), w.normalized()).toRotationMatrix() *
                                  shot.T_base_flange.linear();
    shot.T_base_flange.translation() +=
        util::DrawVector3<Eigen::Vector3d>([&] { return translation_m(random); });
  }
  SaveCalibrationDataset(rendered.dataset);
  CalibrateOptions options;
  options.dh = rendered.truth.dh;
  const CellCalibration calibration = CalibrateCell(LoadCalibrationDataset(dir.path()), options);
  const CalibrationResiduals& r = calibration.residuals;
  std::cout << "noisy arm: kept " << r.hand_eye_method << " " << r.hand_eye_loo_rotation_deg
            << " deg / " << r.hand_eye_loo_translation_mm << " mm; runner-up "
            << r.alternative_method << " " << r.alternative_loo_rotation_deg << " deg / "
            << r.alternative_loo_translation_mm << " mm\n";
  EXPECT_LE(r.hand_eye_loo_rotation_deg / 0.01 + r.hand_eye_loo_translation_mm / 0.1,
            r.alternative_loo_rotation_deg / 0.01 + r.alternative_loo_translation_mm / 0.1);
  // Not the refinement held by the UR5's prior; the one with the noise read from the data is
  // the kept one or the runner-up (measured: 0.039 deg / 0.44 mm estimated for 0.05 / 0.5).
  EXPECT_NE(r.hand_eye_method, "refined");
  EXPECT_TRUE(r.hand_eye_method.find("robot noise") != std::string::npos ||
              r.alternative_method.find("robot noise") != std::string::npos)
      << r.hand_eye_method << " / " << r.alternative_method;
  EXPECT_LT(
      (calibration.T_flange_cam.translation() - rendered.truth.T_flange_cam.translation()).norm(),
      2e-3);
}

TEST(CalibrationDataset, MissingFieldsAreNamedWithTheirShot) {
  testing::TempDir dir("avc-calibration-fields");
  const auto error_of = [&](const std::string& shot) {
    testing::WriteFile(dir / "dataset.json",
                       R"({"format": "avc-calibration-dataset", "version": 1, "board": )"
                       R"({"cols": 9, "rows": 6, "square": 0.025}, "shots": [)" +
                           shot + "]}");
    try {
      LoadCalibrationDataset(dir.path());
    } catch (const std::runtime_error& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  const std::string pose = "[1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]";
  EXPECT_NE(
      error_of(R"({"image": "tt_0.png", "purpose": "turntable", "T_base_flange": )" + pose + "}")
          .find(R"(shot 0 (tt_0.png): no "table_angle")"),
      std::string::npos)
      << "a turntable shot needs its angle";
  EXPECT_NE(error_of(R"({"image": "he_0.png", "purpose": "hand_eye"})")
                .find(R"(shot 0 (he_0.png): no "T_base_flange")"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"purpose": "hand_eye", "T_base_flange": )" + pose + "}")
                .find(R"(shot 0: no "image")"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"image": "he_0.png", "purpose": "wobble", "T_base_flange": )" + pose + "}")
                .find(R"(unknown purpose "wobble")"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"image": "he_0.png", "purpose": "hand_eye", "table_angle": null, )"
                     R"("T_base_flange": )" +
                     pose + "}")
                .find(R"("table_angle" must be a finite number)"),
            std::string::npos);
  // A hand-eye shot without an angle passes the fields (the missing image is the next problem).
  EXPECT_NE(
      error_of(R"({"image": "he_0.png", "purpose": "hand_eye", "T_base_flange": )" + pose + "}")
          .find("does not exist"),
      std::string::npos);
}

TEST(CalibrationDataset, RefusesBadDatasetsNamingTheShot) {
  testing::TempDir dir("avc-calibration-dataset");
  CalibrationDataset dataset;
  dataset.folder = dir.path();
  dataset.shots.push_back(
      {"images/missing.png", ShotPurpose::kHandEye, 0, Eigen::Isometry3d::Identity()});
  SaveCalibrationDataset(dataset);
  const auto error_of = [&] {
    try {
      LoadCalibrationDataset(dir.path());
    } catch (const std::runtime_error& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error_of().find("shot 0: image"), std::string::npos) << error_of();
  EXPECT_NE(error_of().find("does not exist"), std::string::npos);

  fs::create_directories(dir / "images");
  testing::WriteFile(dir / "images" / "missing.png", "not an image");
  dataset.shots[0].T_base_flange.matrix()(0, 3) = std::nan("");
  SaveCalibrationDataset(dataset);
  EXPECT_NE(error_of().find("shot 0 (images/missing.png): T_base_flange must be 16 finite numbers"),
            std::string::npos)
      << error_of();
  dataset.shots[0].T_base_flange.matrix()(0, 3) = 0;
  dataset.shots[0].T_base_flange.matrix()(0, 0) = 2;  // not a rotation
  SaveCalibrationDataset(dataset);
  EXPECT_NE(error_of().find("T_base_flange is not a rigid transform"), std::string::npos)
      << error_of();

  // A readable dataset whose images hold no board: refused, not solved.
  dataset.shots[0].T_base_flange = Eigen::Isometry3d::Identity();
  SaveCalibrationDataset(dataset);
  EXPECT_THROW(CalibrateCell(LoadCalibrationDataset(dir.path()), CalibrateOptions{}),
               std::runtime_error);

  testing::WriteFile(dir / "dataset.json",
                     R"({"format": "avc-calibration-dataset", "version": 7})");
  EXPECT_NE(error_of().find("version 7 is not supported"), std::string::npos) << error_of();
}

}  // namespace
}  // namespace avc::calibration
