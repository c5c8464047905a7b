#pragma once

// A "true" cell drawn around the nominal one: every quantity the calibrator estimates (and the
// arm's factory-calibration deltas, which it does not) is off by a bounded random amount.

#include <cstdint>
#include <string>

#include "sim/cell/cell_truth.h"

namespace avc::sim {

// Largest departure from nominal of each quantity; each is drawn uniformly within its bound
// (per component for lengths and coefficients, as a rotation angle about a uniformly random
// axis for rotations).
struct PerturbationScales {
  double dh_length_m = 1e-3;          // every a and d
  double dh_alpha_rad = 5e-4;         // every alpha
  double dh_theta_offset_rad = 5e-4;  // every theta offset
  double base_translation_m = 0.01;   // robot base position on the table, per axis
  double base_rotation_rad = 0.01;
  double axis_tilt_rad = 0.005;    // turntable axis away from the table z axis
  double centre_offset_m = 0.002;  // turntable centre in the table plane, per axis
  double hand_eye_translation_m = 0.005;
  double hand_eye_rotation_rad = 0.01;
  double focal_relative = 0.02;  // fx and fy, each as a fraction of nominal
  double principal_point_px = 8;
  double k1_k2 = 0.02;
  double k3 = 0.01;
  double p1_p2 = 2e-4;

  // Empty when every bound is finite and non-negative, else the first bad one.
  std::string Validate() const;
};

// The nominal cell perturbed by draws from `seed` (same seed, same cell, bit for bit). Throws
// std::invalid_argument when `scales` is invalid.
CellTruth PerturbedCell(uint32_t seed, const PerturbationScales& scales = {});

}  // namespace avc::sim
