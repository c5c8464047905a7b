#pragma once

// What `RunClusteringComparison` runs and how: the injected method and scorer, timing repeats,
// the dense-spectral size cap and each baseline's options.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "bench/clustering/baselines/ipddp.h"
#include "bench/clustering/baselines/kmeans.h"
#include "bench/clustering/baselines/region_growing.h"
#include "bench/clustering/baselines/spectral_dense.h"
#include "bench/clustering/baselines/spectral_sparse.h"
#include "core/cluster/point_set.h"

namespace avc::bench {

using ClusterFunction = std::function<cluster::Assignment(const cluster::PointSet&)>;
// Accuracy in [0, 1] of an assignment against ground-truth labels (e.g.
// CorrectlyClusteredFraction).
using ScoreFunction =
    std::function<double(const cluster::Assignment&, const std::vector<int32_t>& labels)>;

struct ComparisonOptions {
  ClusterFunction ours;  // the paper's method; omitted from the table when empty
  std::string ours_name = "ours";
  ScoreFunction score;  // accuracy is reported as null when empty or a set has no labels

  int repeats = 3;  // timed runs per method and set; the median is reported
  // A method whose first run takes longer than this is not repeated (dense spectral at 3k points
  // takes tens of seconds).
  double single_run_above_ms = 5000;
  // K for k-means, iPDDP (max clusters) and spectral; 0: the number of distinct ground-truth
  // labels (kUnassigned excluded) of each set.
  int clusters = 0;
  // Sets with more points skip dense spectral (O(n^3) time, n^2 memory); 0: no cap.
  size_t dense_spectral_max_points = 1500;

  // Per-baseline options; their cluster counts are overridden by the K above.
  cluster::baselines::KMeansOptions kmeans;
  cluster::baselines::IpddpOptions ipddp;
  cluster::baselines::DenseSpectralOptions dense_spectral;
  cluster::baselines::SparseSpectralOptions sparse_spectral;
  cluster::baselines::RegionGrowingOptions region_growing;
};

}  // namespace avc::bench
