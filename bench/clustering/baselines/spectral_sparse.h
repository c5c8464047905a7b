#pragma once

// Sparse spectral baseline, the fair "fast spectral": symmetric kNN Gaussian affinity, normalised
// D^-1/2 W D^-1/2, top K eigenvectors by implicitly restarted Lanczos (Spectra, with deflation for
// the repeated eigenvalue 1 of a disconnected graph), row-normalised, k-means. Near-linear in n
// instead of the dense solver's n^3.

#include <cstdint>

#include "bench/clustering/baselines/lanczos_top_eigenvectors.h"
#include "core/cluster/point_set.h"

namespace avc::cluster::baselines {

struct SparseSpectralOptions {
  int clusters = 8;     // K
  int neighbours = 10;  // k of the kNN graph; sigma = median distance to the k-th
  LanczosOptions lanczos;
  int restarts = 5;  // of the final k-means
  uint64_t seed = 1;
};

// Throws std::invalid_argument for an empty or non-finite set or bad options, and
// std::runtime_error when Lanczos does not converge.
Assignment SparseSpectralClustering(const PointSet& set, const SparseSpectralOptions& options);

}  // namespace avc::cluster::baselines
