#pragma once

// Where the arm goes during `avc calibrate collect`: hand-eye poses spread in elevation, azimuth,
// distance and roll over the board (rotations about several axes, as AX=ZB needs), then one
// high pose that keeps the whole board in view while the table turns. Planned with the nominal
// cell geometry (where the table roughly is from the robot, the nominal hand-eye); every pose
// is kept only if the UR5 reaches it, the nominal camera sees every corner with a margin and,
// when the arm's envelope is given, the joint move there from the pose before passes it.

#include <optional>
#include <vector>

#include "core/calibration/board/chessboard_spec.h"
#include "core/cell/cell_model.h"
#include "core/kinematics/dh_parameters.h"
#include "core/kinematics/safety_envelope.h"

namespace avc::calibrator {

struct CalibrationPlanOptions {
  int hand_eye_poses = 12;
  int table_angles = 10;  // evenly spaced over a full turn
  // The envelope avc-robot enforces, as kinematics::PlanningEnvelope gives it; unset: none.
  std::optional<kinematics::SafetyEnvelope> envelope;
};

struct CalibrationPlan {
  std::vector<kinematics::JointVector> hand_eye;
  kinematics::JointVector turntable_pose;
  std::vector<double> table_angles;  // radians
};

// Throws std::runtime_error when fewer than the asked poses are reachable and fully visible.
CalibrationPlan PlanCalibration(const cell::CellModel& nominal,
                                const calibration::ChessboardSpec& board,
                                const kinematics::JointVector& start,
                                const CalibrationPlanOptions& options);

}  // namespace avc::calibrator
