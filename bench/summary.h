#pragma once

// Order statistics for benchmark reports.

#include <cstddef>
#include <vector>

namespace avc::bench {

struct Summary {
  size_t count = 0;
  double median = 0;
  double p90 = 0;
  double p99 = 0;
  double max = 0;
};

// Nearest-rank percentiles; an empty sample gives all zeros.
Summary Summarize(std::vector<double> values);

}  // namespace avc::bench
