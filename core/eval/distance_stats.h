#pragma once

// Summaries of a set of point-to-surface distances: the accuracy and completeness figures.

#include <cstddef>
#include <vector>

namespace avc::eval {

struct DistanceStats {
  size_t count = 0;  // when 0 the other fields are meaningless (left 0)
  double rmse = 0;
  double mean = 0;
  double median = 0;
  double p90 = 0;  // 90th percentile: Middlebury's accuracy
  double max = 0;
};

// Percentiles interpolate linearly between order statistics (numpy's default). Sums run in
// index order, so the result depends on the values only, not on how they were computed.
DistanceStats Summarize(const std::vector<double>& distances);

// Fraction of distances <= threshold; 0 for no distances.
double FractionWithin(const std::vector<double>& distances, double threshold);

// Harmonic mean of precision and recall; 0 when both are 0.
double FScore(double precision, double recall);

}  // namespace avc::eval
