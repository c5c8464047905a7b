#include "bench/calibration/hand_eye/error_statistics.h"

#include <algorithm>
#include <cmath>

namespace avc::bench {

ErrorStatistics DescribeErrors(std::vector<double> values) {
  if (values.empty()) return {};
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  const double median = n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
  const size_t rank = static_cast<size_t>(std::ceil(0.9 * static_cast<double>(n)));
  return {median, values[std::clamp<size_t>(rank, 1, n) - 1], values.back()};
}

nlohmann::json ToJson(const ErrorStatistics& statistics) {
  return {{"median", statistics.median}, {"p90", statistics.p90}, {"max", statistics.max}};
}

}  // namespace avc::bench
