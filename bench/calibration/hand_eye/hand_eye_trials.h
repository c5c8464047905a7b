#pragma once

// `avc bench calibration` (hand-eye part): Monte-Carlo trials of robot-world/hand-eye
// calibration on synthetic cells (hand_eye_scenario.h), comparing in one run our Dornaika &
// Horaud closed form, its Ceres reprojection refinement and OpenCV's SHAH on identical inputs.
// Errors against the truth: hand-eye = T_flange_cam (camera pose on the flange), robot-world =
// T_base_board (board pose in the robot base); geodesic rotation angle in degrees, translation
// distance in millimetres. Trials run in parallel, each from its own seed, so the numbers do not
// depend on thread timing.

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "bench/calibration/hand_eye/hand_eye_scenario.h"
#include "core/calibration/hand_eye/reprojection_refinement.h"

namespace avc::bench {

struct HandEyeAcceptance {
  double median_rotation_deg = 0.02;  // closed form, hand-eye and robot-world
  double median_translation_mm = 0.2;
  double shah_agreement_deg = 0.01;  // closed form vs SHAH, every trial
  double shah_agreement_mm = 0.05;
  // Ceres' median may exceed the closed form's by this much and still count as "no worse"
  // (rounding on noise-free data).
  double ceres_slack_deg = 1e-9;
  double ceres_slack_mm = 1e-9;
};

struct HandEyeTrialOptions {
  std::string name = "noisy";
  int trials = 200;
  uint64_t seed = 1;
  HandEyeScenarioOptions scenario;
  calibration::hand_eye::RefinementOptions refinement;
  HandEyeAcceptance acceptance;
};

// The cases of the benchmark, 10 poses and 200 trials each, fixed seeds, the cell's 1280x960
// camera (fx 1500 px): noise-free, and 0.5 px corner noise with 0.005 deg / 0.05 mm robot noise.
// The third repeats the noisy case with a Canon 650D-like setup (5184x3456, fx 4186 px, 30 mm
// squares, 0.35-0.6 m), the camera the acceptance targets were set for.
HandEyeTrialOptions NoiseFreeHandEyeCase();
HandEyeTrialOptions NoisyHandEyeCase();
HandEyeTrialOptions HighResolutionHandEyeCase();

// One case: error statistics per method, closed form vs SHAH agreement, reprojection RMS,
// failed trials with their reasons, and which acceptance targets are met. Throws
// std::invalid_argument for trials < 1 or invalid scenario options.
nlohmann::json RunHandEyeTrials(const HandEyeTrialOptions& options);

// All three cases: {"cases": [...], "acceptance_met": bool (every case's "all"), "seconds"}.
nlohmann::json RunHandEyeBenchmark(int trials = 200);

// A human-readable table of RunHandEyeTrials or RunHandEyeBenchmark output.
std::string FormatHandEyeTable(const nlohmann::json& results);

}  // namespace avc::bench
