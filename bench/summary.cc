#include "bench/summary.h"

#include <algorithm>
#include <cmath>

namespace avc::bench {
namespace {

double NearestRank(const std::vector<double>& sorted, double percentile) {
  const size_t rank =
      static_cast<size_t>(std::ceil(percentile / 100.0 * static_cast<double>(sorted.size())));
  return sorted[std::clamp<size_t>(rank, 1, sorted.size()) - 1];
}

}  // namespace

Summary Summarize(std::vector<double> values) {
  Summary summary;
  if (values.empty()) return summary;
  std::sort(values.begin(), values.end());
  summary.count = values.size();
  summary.median = values.size() % 2 == 1
                       ? values[values.size() / 2]
                       : 0.5 * (values[values.size() / 2 - 1] + values[values.size() / 2]);
  summary.p90 = NearestRank(values, 90);
  summary.p99 = NearestRank(values, 99);
  summary.max = values.back();
  return summary;
}

}  // namespace avc::bench
