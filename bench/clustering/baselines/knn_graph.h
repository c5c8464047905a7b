#pragma once

// k nearest neighbours of every point (exact, PCL's FLANN k-d tree), for the sparse affinity.

#include <cstdint>
#include <vector>

#include "core/cluster/point_set.h"

namespace avc::cluster::baselines {

struct KnnGraph {
  // neighbours[i]: up to k other points nearest to point i, nearest first.
  std::vector<std::vector<int32_t>> neighbours;
  std::vector<std::vector<float>> squared_distances;
};

KnnGraph BuildKnnGraph(const PointSet& set, int k);

}  // namespace avc::cluster::baselines
