#pragma once

// Dense spectral baseline as in the paper's comparison (Ng-Jordan-Weiss): full Gaussian affinity,
// normalised D^-1/2 A D^-1/2, all eigenvectors by Eigen's SelfAdjointEigenSolver (O(n^3): tens of
// seconds at 3000 points), top K row-normalised, k-means.

#include <cstdint>

#include "core/cluster/point_set.h"

namespace avc::cluster::baselines {

struct DenseSpectralOptions {
  int clusters = 8;         // K
  int sigma_neighbour = 7;  // sigma = median distance to this nearest neighbour
  int restarts = 5;         // of the final k-means
  uint64_t seed = 1;
};

// Throws std::invalid_argument for an empty or non-finite set or K outside [1, points].
Assignment DenseSpectralClustering(const PointSet& set, const DenseSpectralOptions& options);

}  // namespace avc::cluster::baselines
