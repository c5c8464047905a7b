#pragma once

// Monte-Carlo benchmark of turntable axis calibration: the paper's opposite-pairs line
// intersection (baseline) against our closed-form circle/screw fit and the Ceres fit of all
// poses, on the same simulated captures (bench/calibration/turntable/turntable_scenario.h).
// Seeded and single-threaded: the same options give the same JSON.

#include <cmath>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

namespace avc::bench {

struct TurntableTrialOptions {
  int trials = 200;
  int angles = 10;               // evenly spread over a full turn
  double position_sigma = 1e-4;  // board origin noise, metres per axis (0.1 mm)
  // Orientation noise matching 0.1 mm at the 0.1 m lever arm of a board: 1 mrad per axis.
  double orientation_sigma = 1e-3;
  double angle_sigma = 0.1 * M_PI / 180;  // table angle error
  double axis_tilt = 1 * M_PI / 180;      // true axis off the table frame's z
  double board_offset = 0.1;              // board origin distance from the axis, metres
  uint64_t seed = 20260101;

  // Empty when usable; else a sentence naming the bad option.
  std::string Validate() const;
};

// {"options": {...}, "methods": {name: {"centre_mm": {median, p90, max}, "axis_deg": {...},
//  "failures": n}}, "acceptance": {...}}; methods: line_intersection (paper), circle_screw,
// ceres_fit. Throws std::invalid_argument for unusable options.
nlohmann::json RunTurntableTrials(const TurntableTrialOptions& options);

// A human-readable table of RunTurntableTrials' result.
std::string FormatTurntableTrials(const nlohmann::json& result);

}  // namespace avc::bench
