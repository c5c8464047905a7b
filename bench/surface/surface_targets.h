#pragma once

// The surfacer's acceptance targets (issue 9), checked on `avc bench surface` results.

#include <string>
#include <vector>

#include "bench/surface/surface_case.h"

namespace avc::bench {

struct TargetCheck {
  std::string target;
  bool met = false;
  std::string detail;  // the figures behind the verdict
};

// On every preset, for each of our two clusterings: area ratio in [0.9, 1.1]; RMSE below every
// baseline's; >= 90 % of leaves in one connected piece; the height trait within 2 % of the
// leaves' (the area trait is the area ratio); at most 10 s for the points.
std::vector<TargetCheck> CheckSurfaceTargets(const std::vector<SurfaceCaseResult>& cases);

}  // namespace avc::bench
