#pragma once

// The seed paper's turntable calibration (Gibbs et al., section 2.1), kept as the baseline: the
// board origin is measured at several table angles, origins at opposite angles (theta and
// theta + 180 deg) are joined by lines, and the least-squares intersection of those lines is the
// centre of rotation. The paper gives no axis direction; for comparison this baseline reports the
// normal of the plane through the paired origins.

#include <cmath>
#include <vector>

#include "core/calibration/turntable/turntable_views.h"

namespace avc::calibration {

struct OppositePairsOptions {
  double pair_tolerance = 1 * M_PI / 180;   // |angle difference - 180 deg| to count as opposite
  double min_line_angle = 10 * M_PI / 180;  // the joined lines must not all be parallel
  TurntableInputLimits limits;
};

// Throws std::invalid_argument (naming the method) for invalid views, fewer than two opposite
// pairs, or pair lines that are all nearly parallel.
TurntableAxis OppositePairsCentre(const std::vector<TurntableView>& views,
                                  const OppositePairsOptions& options = {});

}  // namespace avc::calibration
