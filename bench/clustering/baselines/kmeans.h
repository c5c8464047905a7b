#pragma once

// k-means baseline on point positions (the paper's Table 2): needs K and cuts leaves arbitrarily.

#include <cstdint>

#include "core/cluster/point_set.h"

namespace avc::cluster::baselines {

struct KMeansOptions {
  int clusters = 8;  // K
  int restarts = 5;
  int max_iterations = 100;
  uint64_t seed = 1;
};

// Throws std::invalid_argument for an empty or non-finite set or K outside [1, points].
Assignment KMeansClustering(const PointSet& set, const KMeansOptions& options);

}  // namespace avc::cluster::baselines
