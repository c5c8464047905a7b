#pragma once

// Simulated turntable calibration captures: a board lying on the turntable, seen from a fixed
// frame at several commanded table angles, through the simulated cell's own turntable model
// (sim::TableFromWorld), with board-pose noise and table angle errors. Shared by the turntable
// benchmark and the turntable tests.

#include <Eigen/Geometry>
#include <vector>

#include "core/calibration/turntable/turntable_views.h"
#include "sim/cell/random.h"

namespace avc::bench {

struct TurntableScenario {
  Eigen::Vector3d axis_table = Eigen::Vector3d::UnitZ();  // true axis, table frame
  Eigen::Vector3d centre_table = Eigen::Vector3d::Zero();
  Eigen::Isometry3d T_fixed_table = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d T_table_board0 = Eigen::Isometry3d::Identity();  // board at angle 0

  // Ground truth in the fixed frame: the axis, and its point level with the board origin.
  calibration::TurntableAxis TruthInFixedFrame() const;
};

struct TurntableNoise {
  double position_sigma = 0;     // metres, per axis, on the board origin
  double orientation_sigma = 0;  // radians, per axis, rotation-vector noise in the board frame
  double angle_sigma = 0;        // radians, true table angle minus commanded
};

// A random but realistic capture: axis tilted by `axis_tilt` (radians) in a random direction
// through a centre within 5 mm of the table origin, the board flat on the table with its origin
// `board_offset` metres off the axis, the fixed frame a camera 0.5 m away looking down at 30-60
// degrees elevation.
TurntableScenario RandomTurntableScenario(sim::DeterministicRandom& random, double axis_tilt,
                                          double board_offset);

// Views at `angles` commanded angles evenly spread over a full turn (starting at 0).
std::vector<calibration::TurntableView> SimulateTurntableViews(const TurntableScenario& scenario,
                                                               int angles,
                                                               const TurntableNoise& noise,
                                                               sim::DeterministicRandom& random);

// Angle between unit axes (radians) and distance between centres (metres).
double AxisError(const calibration::TurntableAxis& estimate,
                 const calibration::TurntableAxis& truth);
double CentreError(const calibration::TurntableAxis& estimate,
                   const calibration::TurntableAxis& truth);

}  // namespace avc::bench
