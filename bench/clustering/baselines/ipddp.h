#pragma once

// iPDDP baseline (Tasoulis, Tasoulis & Plagianakos 2010; rules of HiPart's iPDDP): split a leaf
// at the midpoint of the largest gap of its projection on the first principal component, within
// the central percentile band; always split the leaf with the largest such gap next.

#include "core/cluster/point_set.h"

namespace avc::cluster::baselines {

struct IpddpOptions {
  int max_clusters = 8;      // stop when this many leaves exist
  double percentile = 0.1;   // gaps are searched between the p and 1-p quantiles
  int min_sample_split = 5;  // a leaf needs more points than this to be split
};

// Throws std::invalid_argument for an empty or non-finite set or bad options.
Assignment IpddpClustering(const PointSet& set, const IpddpOptions& options);

}  // namespace avc::cluster::baselines
