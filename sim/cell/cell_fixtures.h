#pragma once

// The fixed things in the simulated cell that the arm must keep clear of: the bench that the
// robot's pedestal and the turntable stand on, and the turntable under the plant. From them, the
// fixed part of the safety envelope (kinematics::SafetyEnvelope) that `avc demo` and the
// multi-process tests start avc-robot with and give the planner. A real cell measures its own and
// passes the same numbers to `avc robot` and `avc scan` (--table-z, --keep-out).

#include <string>
#include <vector>

#include "core/kinematics/safety_envelope.h"
#include "sim/cell/cell_truth.h"

namespace avc::sim {

struct CellFixtures {
  double turntable_height_m = 0.06;  // the turntable's top above the bench
  double turntable_radius_m = 0.18;  // its platter, about the turntable axis
  double clearance_m = 0.02;         // every checked point of the arm keeps this from both
};

// The bench as the table plane (its base-frame height, with the fixtures' clearance) and the
// turntable as a keep-out cylinder about the axis grown by the clearance, up to its top plus the
// clearance. Assumes the turntable axis is vertical in the base frame, as a cell is built.
kinematics::SafetyEnvelope FixturesEnvelope(const CellTruth& cell,
                                            const CellFixtures& fixtures = {});

// FixturesEnvelope of the nominal cell with the default fixtures: what a lab would measure for
// the simulated cell (which differs from the nominal one by millimetres). The demo's and the
// multi-process tests' avc-robot run with it, and their planners check views against it.
kinematics::SafetyEnvelope NominalCellEnvelope();

// The `avc robot` arguments that give it that envelope's table plane and keep-out cylinder.
std::vector<std::string> RobotEnvelopeArguments(const kinematics::SafetyEnvelope& envelope);

}  // namespace avc::sim
