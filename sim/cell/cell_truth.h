#pragma once

// The simulated cell as it really is: a cell model (core/cell/cell_model.h) with the arm's true
// kinematics, where the robot truly stands, the turntable's true axis, the true hand-eye and the
// camera's intrinsics. The sim renders and reports from it; the drivers and the calibrator
// assume the nominal arm and must recover the rest. The simulator builds on the production cell
// model, never the other way round.

#include "core/cell/cell_model.h"

namespace avc::sim {

using CellTruth = cell::CellModel;
using cell::CameraAt;
using cell::NominalCell;
using cell::TableFromWorld;

}  // namespace avc::sim
