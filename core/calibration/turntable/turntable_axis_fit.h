#pragma once

// Maximum-likelihood turntable axis with Ceres: all board poses against the commanded angles,
//   R_k = Rot(a, theta_k + delta_k) R_0,   p_k = c + Rot(a, theta_k + delta_k) (p_0 - c),
// unknowns the axis line (c, a) on ceres::LineManifold (4 DoF), the board pose at angle 0
// (R_0 as a rotation-vector update of its start, p_0) and, optionally, one angle offset delta_k
// per view with a Gaussian prior of the table's angle accuracy, so a table that stops a little
// off its commanded angle does not pull the axis. Residuals are weighted by the expected board
// position / orientation noise. Starts from CircleScrewAxis; single-threaded, so deterministic.

#include <cmath>
#include <vector>

#include "core/calibration/turntable/circle_screw_axis.h"
#include "core/calibration/turntable/turntable_views.h"

namespace avc::calibration {

struct TurntableFitOptions {
  double position_sigma = 1e-4;     // board origin noise, metres
  double orientation_sigma = 1e-3;  // board orientation noise, radians
  // Table angle accuracy (radians, 1 sigma); 0 trusts the commanded angles exactly.
  double angle_sigma = 0.1 * M_PI / 180;
  int max_iterations = 100;
  TurntableInputLimits limits;
};

struct TurntableFit {
  TurntableAxis axis;
  Eigen::Isometry3d T_fixed_board0 = Eigen::Isometry3d::Identity();  // board pose at angle 0
  std::vector<double> angle_offsets;  // delta_k per view (radians); zeros when not estimated
  double rms_position = 0;            // metres, over views
  double rms_orientation = 0;         // radians, over views
  int iterations = 0;
};

// Throws std::invalid_argument (naming the method) for invalid/degenerate views or options and
// std::runtime_error when the solver fails.
TurntableFit FitTurntableAxis(const std::vector<TurntableView>& views,
                              const TurntableFitOptions& options = {});

}  // namespace avc::calibration
