#pragma once

// The calibration target of the simulated cell drawn as a scene: the chessboard the calibration
// plans for (core/calibration/board/chessboard_spec.h), lying on the turntable.

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "core/calibration/board/chessboard_spec.h"
#include "sim/scene/scene.h"

namespace avc::sim {

using calibration::ChessboardCorners;
using calibration::ChessboardSpec;

// (inner_cols + 1) x (inner_rows + 1) black and white squares (the corner square is black) and
// a white margin, labelled labels::kTarget. Throws std::invalid_argument for a bad spec.
Scene ChessboardScene(const ChessboardSpec& spec);

}  // namespace avc::sim
