#pragma once

// Closed-form turntable axis and centre. The axis direction comes from the board orientations:
// every pair of views k, l is rotated by R_l R_k^T = Rot(a, theta_l - theta_k), whose skew part
// is sin(theta_l - theta_k) a; summing those, signed by the commanded angle difference, weighs
// each pair by sin^2 and needs no quaternion sign bookkeeping. The centre comes from the circle
// the board origin travels: origins projected on the plane normal to the axis, Kasa's algebraic
// circle fit, and the mean height along the axis. Neither step uses the commanded angle values
// beyond their signs, so table angle errors barely matter.

#include <vector>

#include "core/calibration/turntable/turntable_views.h"

namespace avc::calibration {

struct CircleScrewOptions {
  TurntableInputLimits limits;
};

// Throws std::invalid_argument (naming the method) for invalid or degenerate views: no rotation
// between them, or board origins (nearly) on the axis.
TurntableAxis CircleScrewAxis(const std::vector<TurntableView>& views,
                              const CircleScrewOptions& options = {});

}  // namespace avc::calibration
