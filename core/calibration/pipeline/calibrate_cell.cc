#include "core/calibration/pipeline/calibrate_cell.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "core/calibration/board/board_pose.h"
#include "core/calibration/board/chessboard_detection.h"
#include "core/calibration/hand_eye/robot_world_hand_eye.h"
#include "core/calibration/pipeline/hand_eye_choice.h"
#include "core/util/upper_median.h"

namespace avc::calibration {
namespace {

struct DetectedShot {
  const CalibrationShot* shot;
  BoardDetection detection;
  Eigen::Isometry3d T_cam_board = Eigen::Isometry3d::Identity();
};

std::vector<Eigen::Vector3d> BoardPoints(const Chessboard& board) {
  std::vector<Eigen::Vector3d> points;
  for (const cv::Point3f& p : board.CornerPoints()) points.emplace_back(p.x, p.y, p.z);
  return points;
}

}  // namespace

CellCalibration CalibrateCell(const CalibrationDataset& dataset, const CalibrateOptions& options,
                              CalibrationDetails* details_out,
                              const CalibrationProgress& progress) {
  CalibrationDetails details;
  CellCalibration calibration;
  CalibrationResiduals& residuals = calibration.residuals;
  const auto report = [&](const std::string& stage) {
    if (progress) progress(stage);
  };

  // 1. The board in every image.
  std::vector<DetectedShot> detected;
  for (size_t i = 0; i < dataset.shots.size(); ++i) {
    const CalibrationShot& shot = dataset.shots[i];
    report(fmt::format("finding the board in {} ({}/{})", shot.image, i + 1, dataset.shots.size()));
    try {
      BoardDetection detection = DetectChessboardInFile(dataset.folder / shot.image, dataset.board);
      detection.name = shot.image;
      detected.push_back({&shot, std::move(detection)});
    } catch (const std::exception& error) {
      residuals.rejected.push_back(fmt::format("{}: {}", shot.image, error.what()));
    }
  }

  // 2. Intrinsics from every view with a board.
  report(fmt::format("intrinsics from {} views", detected.size()));
  std::vector<BoardDetection> detections;
  for (const DetectedShot& d : detected) detections.push_back(d.detection);
  if (detections.empty()) {
    throw std::runtime_error("calibration refused: the board was found in no image");
  }
  const IntrinsicsCalibration intrinsics =
      CalibrateIntrinsics(detections, dataset.board, options.intrinsics);
  calibration.intrinsics = intrinsics.intrinsics;
  residuals.intrinsics_rms_px = intrinsics.report.rms_px;
  details.warnings = intrinsics.report.warnings;
  details.distortion_model = intrinsics.report.distortion_model;
  details.distortion_model_reason = intrinsics.report.distortion_model_reason;
  std::vector<DetectedShot> kept;
  for (size_t i = 0; i < detected.size(); ++i) {
    const ViewReport& view = intrinsics.report.views[i];
    if (view.rejected) {
      residuals.rejected.push_back(
          fmt::format("{}: reprojection RMS {:.3f} px, an outlier", view.name, view.rms_px));
      continue;
    }
    detected[i].T_cam_board = view.T_cam_board;
    kept.push_back(detected[i]);
  }

  // 3. Robot-world/hand-eye from the hand-eye shots.
  std::vector<hand_eye::HandEyeObservation> observations;
  std::vector<hand_eye::BoardView> board_views;
  const std::vector<Eigen::Vector3d> board_points = BoardPoints(dataset.board);
  for (const DetectedShot& d : kept) {
    if (d.shot->purpose != ShotPurpose::kHandEye) continue;
    observations.push_back({d.shot->T_base_flange, d.T_cam_board});
    hand_eye::BoardView view;
    view.T_base_flange = d.shot->T_base_flange;
    view.board_points = board_points;
    for (const cv::Point2f& c : d.detection.corners) view.pixels.emplace_back(c.x, c.y);
    board_views.push_back(std::move(view));
    residuals.view_names.push_back(d.shot->image);
  }
  details.hand_eye_views = static_cast<int>(observations.size());
  details.hand_eye_observations = observations;
  details.hand_eye_board_views = board_views;
  report(fmt::format("hand-eye from {} poses", observations.size()));
  const HandEyeChoice choice = ChooseHandEye(observations, board_views, calibration.intrinsics,
                                             options.diversity, options.refinement);
  const HandEyeCandidate& chosen = choice.chosen;
  report(fmt::format(
      "hand-eye: {} (leave-one-out {:.4f} deg / {:.3f} mm; {} {:.4f} deg / "
      "{:.3f} mm)",
      chosen.method, chosen.loo_rotation_deg, chosen.loo_translation_mm, choice.alternative.method,
      choice.alternative.loo_rotation_deg, choice.alternative.loo_translation_mm));
  calibration.T_flange_cam = chosen.T_cam_flange.inverse();
  residuals.view_rms_px = chosen.view_rms_px;
  residuals.hand_eye_rms_px = chosen.rms_px;
  residuals.hand_eye_method = chosen.method;
  residuals.hand_eye_loo_rotation_deg = chosen.loo_rotation_deg;
  residuals.hand_eye_loo_translation_mm = chosen.loo_translation_mm;
  residuals.alternative_method = choice.alternative.method;
  residuals.alternative_rms_px = choice.alternative.rms_px;
  residuals.alternative_loo_rotation_deg = choice.alternative.loo_rotation_deg;
  residuals.alternative_loo_translation_mm = choice.alternative.loo_translation_mm;
  details.closed_form_rms_px = choice.closed_form_rms_px;
  std::vector<double> rotation_deg, translation_mm;
  for (const hand_eye::PoseResidual& r :
       hand_eye::PoseResiduals(observations, chosen.T_board_base, chosen.T_cam_flange)) {
    rotation_deg.push_back(r.rotation_deg);
    translation_mm.push_back(r.translation_mm);
  }
  residuals.hand_eye_rotation_deg = UpperMedian(rotation_deg);
  residuals.hand_eye_translation_mm = UpperMedian(translation_mm);

  // 4. The turntable axis from the board carried into the base frame.
  std::vector<TurntableView> table_views;
  for (const DetectedShot& d : kept) {
    if (d.shot->purpose != ShotPurpose::kTurntable) continue;
    table_views.push_back(
        {d.shot->table_angle, d.shot->T_base_flange * calibration.T_flange_cam * d.T_cam_board});
  }
  details.turntable_views = static_cast<int>(table_views.size());
  if (table_views.empty()) {
    // A hand-eye-only dataset (a robot without our turntable, say): intrinsics, hand-eye and
    // robot-world; the board's pose stands where the table frame would be.
    report("no turntable shots: the turntable is not calibrated");
    calibration.turntable_calibrated = false;
    calibration.T_base_table = chosen.T_board_base.inverse();
    calibration.T_table_board = Eigen::Isometry3d::Identity();
  } else {
    report(fmt::format("turntable axis from {} angles", table_views.size()));
    const TurntableFit fit = FitTurntableAxis(table_views, options.turntable);
    details.turntable_axis_base = fit.axis;
    residuals.turntable_centre_rms_mm = fit.rms_position * 1000;
    residuals.turntable_angles = static_cast<int>(table_views.size());
    calibration.T_base_table = TableFrame(fit.axis, fit.T_fixed_board0.translation());
    calibration.T_table_board = calibration.T_base_table.inverse() * fit.T_fixed_board0;
  }

  calibration.dh = options.dh;
  calibration.note = fmt::format(
      "{} images, {} used: {} hand-eye poses, {} table angles{}; board {}x{} {} mm; "
      "distortion {}",
      dataset.shots.size(), kept.size(), details.hand_eye_views, details.turntable_views,
      calibration.turntable_calibrated ? "" : " (turntable not calibrated)", dataset.board.cols,
      dataset.board.rows, dataset.board.square_size * 1000, details.distortion_model);
  if (const std::string problem = calibration.Validate(); !problem.empty()) {
    throw std::runtime_error("calibration refused: " + problem);
  }
  if (details_out) *details_out = details;
  return calibration;
}

}  // namespace avc::calibration
