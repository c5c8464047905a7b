#pragma once

// The whole calibration from a dataset (paper §2.1; README.md, Calibration): find the board in
// every image, intrinsics from all views, robot-world/hand-eye from the hand-eye shots (closed
// form, then refined on the reprojection of every corner), the turntable axis from the turntable
// shots (board poses carried into the base frame through the hand-eye), and the table frame.
// A dataset with no turntable shots gives a hand-eye-only calibration (turntable_calibrated
// false).
// Views that fail (board not found, unreadable, outliers) are left out and listed; a dataset
// that cannot determine the calibration is refused with the reason, never solved wrongly.

#include <functional>
#include <string>

#include "core/calibration/board/intrinsics_calibration.h"
#include "core/calibration/cell/cell_calibration.h"
#include "core/calibration/hand_eye/motion_diversity.h"
#include "core/calibration/hand_eye/reprojection_refinement.h"
#include "core/calibration/hand_eye/robot_world_hand_eye.h"
#include "core/calibration/pipeline/calibration_dataset.h"
#include "core/calibration/turntable/turntable_axis_fit.h"

namespace avc::calibration {

struct CalibrateOptions {
  IntrinsicsOptions intrinsics;
  hand_eye::DiversityLimits diversity;
  hand_eye::RefinementOptions refinement;
  TurntableFitOptions turntable;
  // The arm's kinematics stored with the calibration for joint-vector queries.
  kinematics::DhParameters dh = kinematics::NominalUr5();
};

// What each stage found, beyond the calibration itself (for the report).
struct CalibrationDetails {
  int hand_eye_views = 0;
  int turntable_views = 0;
  double closed_form_rms_px = 0;  // the hand-eye closed form's reprojection RMS, before refining
  TurntableAxis turntable_axis_base;
  std::string distortion_model;  // the intrinsics' terms estimated ("given": --intrinsics)
  std::string distortion_model_reason;
  std::vector<std::string> warnings;
  // The hand-eye stage's inputs, for comparing methods on the same detections (benchmarks).
  std::vector<hand_eye::HandEyeObservation> hand_eye_observations;
  std::vector<hand_eye::BoardView> hand_eye_board_views;
};

using CalibrationProgress = std::function<void(const std::string& stage)>;

// Throws std::runtime_error / std::invalid_argument naming the stage and the views when the
// dataset cannot determine the calibration.
CellCalibration CalibrateCell(const CalibrationDataset& dataset, const CalibrateOptions& options,
                              CalibrationDetails* details = nullptr,
                              const CalibrationProgress& progress = {});

}  // namespace avc::calibration
