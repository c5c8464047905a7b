// The calibration poses `avc calibrate collect` plans for the simulated cell: with the arm
// driver's envelope (the bench and the turntable), every move from the arm's start pose through
// the hand-eye poses to the turntable pose passes the driver's own check; without it, the plan
// takes moves the driver would refuse.

#include "services/calibrator/calibration_plan.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "sim/cell/cell_fixtures.h"
#include "sim/cell/view_selection.h"
#include "sim/scene/chessboard_scene.h"

namespace avc::calibrator {
namespace {

// The driver's refusals along the plan's moves, in order.
std::vector<std::string> Refusals(const sim::CellTruth& cell, const CalibrationPlan& plan,
                                  const kinematics::SafetyEnvelope& driver) {
  std::vector<kinematics::JointVector> moves = plan.hand_eye;
  moves.push_back(plan.turntable_pose);
  std::vector<std::string> refusals;
  kinematics::JointVector from = sim::StartJoints(cell);
  for (const kinematics::JointVector& to : moves) {
    const std::string refusal = kinematics::CheckJointMove(driver, cell.dh, from, to, 1.0, 1.0);
    if (!refusal.empty()) refusals.push_back(refusal);
    from = to;
  }
  return refusals;
}

TEST(CalibrationPlan, EveryMoveStaysInsideTheArmsEnvelope) {
  const sim::CellTruth cell = sim::NominalCell();
  const sim::ChessboardSpec board;
  const kinematics::SafetyEnvelope driver = sim::NominalCellEnvelope();
  CalibrationPlanOptions options;
  options.envelope = kinematics::PlanningEnvelope(driver);
  const CalibrationPlan plan = PlanCalibration(cell, board, sim::StartJoints(cell), options);
  EXPECT_EQ(plan.hand_eye.size(), static_cast<size_t>(options.hand_eye_poses));
  const std::vector<std::string> refusals = Refusals(cell, plan, driver);
  EXPECT_TRUE(refusals.empty()) << refusals.front();

  const CalibrationPlan unchecked =
      PlanCalibration(cell, board, sim::StartJoints(cell), CalibrationPlanOptions{});
  EXPECT_FALSE(Refusals(cell, unchecked, driver).empty())
      << "the envelope no longer changes the plan: this test checks nothing";
}

}  // namespace
}  // namespace avc::calibrator
