#pragma once

// Median, 90th percentile and maximum of a sample of errors, as the hand-eye benchmark reports
// them (bench/summary.h computes them).

#include <nlohmann/json.hpp>
#include <vector>

namespace avc::bench {

struct ErrorStatistics {
  double median = 0;  // mean of the two middle values for an even count
  double p90 = 0;     // nearest rank
  double max = 0;
};

// All zeros for an empty sample.
ErrorStatistics DescribeErrors(std::vector<double> values);

nlohmann::json ToJson(const ErrorStatistics& statistics);

}  // namespace avc::bench
