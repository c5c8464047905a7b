#pragma once

// A calibration dataset on disk: the images a calibration run took and, for each, the robot's
// flange pose and the commanded table angle, in `dataset.json` next to an `images/` folder.
// `avc calibrate collect` writes one in the cell; `avc calibrate solve` reads one (from the cell
// or from anywhere else that recorded images with robot poses).
//
//   {"format": "avc-calibration-dataset", "version": 1,
//    "board": {"cols": 9, "rows": 6, "square": 0.025},
//    "shots": [{"image": "images/he_0000.png", "purpose": "hand_eye", "table_angle": 0,
//               "T_base_flange": [16 numbers, row-major]}, ...]}
//
// purpose "hand_eye": table at its zero angle, the arm moving (intrinsics and AX=ZB);
// "turntable": the arm still, the table at table_angle (axis and centre). Every shot also
// serves the intrinsics.

#include <Eigen/Geometry>
#include <filesystem>
#include <string>
#include <vector>

#include "core/calibration/board/chessboard.h"

namespace avc::calibration {

enum class ShotPurpose { kHandEye, kTurntable };

struct CalibrationShot {
  std::string image;  // relative to the dataset folder
  ShotPurpose purpose = ShotPurpose::kHandEye;
  double table_angle = 0;                                           // commanded, radians
  Eigen::Isometry3d T_base_flange = Eigen::Isometry3d::Identity();  // as the controller reported
};

struct CalibrationDataset {
  std::filesystem::path folder;
  Chessboard board;
  std::vector<CalibrationShot> shots;
};

// Throws std::runtime_error naming the file and the shot of any problem (unreadable, wrong
// format or version, a missing image file, a non-finite or non-rigid pose, an unknown purpose).
CalibrationDataset LoadCalibrationDataset(const std::filesystem::path& folder);
void SaveCalibrationDataset(const CalibrationDataset& dataset);

}  // namespace avc::calibration
