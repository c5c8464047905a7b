#include "core/eval/coverage_oracle.h"

#include <fmt/format.h>

#include <stdexcept>

namespace avc::eval {

OracleSelection GreedyCoverageSelection(const std::vector<std::vector<uint8_t>>& seen,
                                        int min_views, size_t max_views) {
  if (min_views < 1) {
    throw std::invalid_argument(fmt::format("coverage oracle: min_views {} < 1", min_views));
  }
  const size_t samples = seen.empty() ? 0 : seen.front().size();
  for (size_t v = 0; v < seen.size(); ++v) {
    if (seen[v].size() != samples) {
      throw std::invalid_argument(
          fmt::format("coverage oracle: candidate {} has {} samples, candidate 0 has {}", v,
                      seen[v].size(), samples));
    }
  }
  OracleSelection selection;
  std::vector<int> counts(samples, 0);
  std::vector<bool> chosen(seen.size(), false);
  size_t covered = 0;
  while (selection.order.size() < max_views) {
    size_t best = seen.size();
    long best_gain = 0;
    for (size_t v = 0; v < seen.size(); ++v) {
      if (chosen[v]) continue;
      long gain = 0;
      for (size_t s = 0; s < samples; ++s) {
        if (seen[v][s] && counts[s] < min_views) gain += counts[s] + 1;
      }
      if (gain > best_gain) {
        best_gain = gain;
        best = v;
      }
    }
    if (best == seen.size()) break;
    chosen[best] = true;
    for (size_t s = 0; s < samples; ++s) {
      if (seen[best][s] && ++counts[s] == min_views) ++covered;
    }
    selection.order.push_back(best);
    selection.coverage.push_back(static_cast<double>(covered) / samples);
  }
  return selection;
}

}  // namespace avc::eval
