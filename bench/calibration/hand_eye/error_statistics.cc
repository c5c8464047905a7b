#include "bench/calibration/hand_eye/error_statistics.h"

#include <utility>

#include "bench/summary.h"

namespace avc::bench {

ErrorStatistics DescribeErrors(std::vector<double> values) {
  const Summary summary = Summarize(std::move(values));
  return {summary.median, summary.p90, summary.max};
}

nlohmann::json ToJson(const ErrorStatistics& statistics) {
  return {{"median", statistics.median}, {"p90", statistics.p90}, {"max", statistics.max}};
}

}  // namespace avc::bench
