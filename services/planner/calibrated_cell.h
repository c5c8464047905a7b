#pragma once

// The cell the planner plans in, from a calibration: on a real cell (and in the simulated one,
// which the orchestrator treats the same way) the planner knows the cell only through
// calibration.yaml, never through the simulator's truth. The calibration's table frame has z on
// the turntable axis with its origin on it, so the axis is z through the origin.

#include "core/calibration/cell/cell_calibration.h"
#include "core/cell/cell_model.h"

namespace avc::planner {

// Throws std::invalid_argument naming the bad field when the calibration is not usable.
cell::CellModel CellModelFromCalibration(const calibration::CellCalibration& calibration);

}  // namespace avc::planner
