#include "core/eval/distance_stats.h"

#include <algorithm>
#include <cmath>

namespace avc::eval {
namespace {

double Percentile(const std::vector<double>& sorted, double q) {
  const double position = q * static_cast<double>(sorted.size() - 1);
  const size_t below = static_cast<size_t>(std::floor(position));
  const size_t above = std::min(below + 1, sorted.size() - 1);
  const double fraction = position - static_cast<double>(below);
  return sorted[below] + fraction * (sorted[above] - sorted[below]);
}

}  // namespace

DistanceStats Summarize(const std::vector<double>& distances) {
  DistanceStats stats;
  stats.count = distances.size();
  if (distances.empty()) return stats;
  double sum = 0;
  double sum_squares = 0;
  for (double d : distances) {
    sum += d;
    sum_squares += d * d;
  }
  const double n = static_cast<double>(distances.size());
  stats.mean = sum / n;
  stats.rmse = std::sqrt(sum_squares / n);
  std::vector<double> sorted = distances;
  std::sort(sorted.begin(), sorted.end());
  stats.median = Percentile(sorted, 0.5);
  stats.p90 = Percentile(sorted, 0.9);
  stats.max = sorted.back();
  return stats;
}

double FractionWithin(const std::vector<double>& distances, double threshold) {
  if (distances.empty()) return 0;
  const size_t within = static_cast<size_t>(std::count_if(
      distances.begin(), distances.end(), [threshold](double d) { return d <= threshold; }));
  return static_cast<double>(within) / static_cast<double>(distances.size());
}

double FScore(double precision, double recall) {
  return precision + recall > 0 ? 2 * precision * recall / (precision + recall) : 0;
}

}  // namespace avc::eval
