#pragma once

// The calibration run in the cell: power the arm, put the table at zero, take the hand-eye
// shots over the board, then the turntable shots from one pose, saving every image with the
// flange pose the controller reported after the arm settled and the commanded table angle.
// The result is a dataset folder that `avc calibrate solve` (or CalibrateCell) turns into a
// calibration.

#include <filesystem>
#include <functional>
#include <string>

#include "core/calibration/pipeline/calibration_dataset.h"
#include "drivers/client/cell_client.h"
#include "services/calibrator/calibration_plan.h"

namespace avc::calibrator {

struct CollectOptions {
  std::filesystem::path folder;  // created; refused when it already holds a dataset
  calibration::Chessboard board;
  CalibrationPlanOptions plan;
  // Rough cell geometry used to plan the poses (where the table is from the robot, the nominal
  // hand-eye and camera); the calibration itself does not depend on it.
  cell::CellModel planning_cell = cell::NominalCell();
};

// Throws std::runtime_error naming the step that failed (a service not ready, a refused or
// failed command, an image that did not arrive).
calibration::CalibrationDataset CollectCalibrationDataset(
    client::CellClient& cell, const CollectOptions& options,
    const std::function<void(const std::string&)>& progress = {});

}  // namespace avc::calibrator
