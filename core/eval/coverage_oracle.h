#pragma once

// How much coverage n views could give, for a planner's report: the views of a candidate set
// chosen greedily by someone who knows the ground truth. A reference, not a planner (a planner
// only knows its proxy). Greedy selection is not guaranteed optimal, so this estimates the best a
// set of candidate views allows; it is not a bound. Deterministic: ties go to the lower index.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace avc::eval {

struct OracleSelection {
  std::vector<size_t> order;     // chosen candidates, first chosen first
  std::vector<double> coverage;  // coverage[k]: fraction of samples covered by order[0..k]
};

// `seen[v][s]` is non-zero when candidate v sees sample s (CoverageModel::SeenBy); a sample is
// covered once min_views chosen views see it. Each step takes the candidate with the largest
// gain, where a not yet covered sample seen by c chosen views adds c + 1 (so views that complete
// samples win over views that start new ones). Stops after max_views or when no candidate adds
// anything. Throws std::invalid_argument for rows of different lengths or min_views < 1.
OracleSelection GreedyCoverageSelection(const std::vector<std::vector<uint8_t>>& seen,
                                        int min_views, size_t max_views);

}  // namespace avc::eval
