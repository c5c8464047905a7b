#pragma once

// Clustering on the command line (`avc cluster`, `avc clusterer`, `avc reconstruct`): the options
// a user may set (the data scales, measured when 0, and the main thresholds of Algorithm 2;
// core/cluster/cluster_plant.h explains each) and the one-line summary of a result.

#include <CLI/CLI.hpp>
#include <string>

#include "services/clusterer/merge_and_cluster.h"

namespace avc::cli {

struct ClusterFlags {
  double spacing_mm = 0;
  double noise_mm = 0;
  double link_factor = cluster::ClusterOptions{}.link_factor;
  int min_cluster_points = 0;
  int merge_min_points = merge::MergeOptions{}.min_points;

  clusterer::ClustererOptions Options() const;
};

void AddClusterFlags(CLI::App* command, ClusterFlags* flags);

// "clusters: 9,153 merged points (of 80,095) in 14 clusters, 12 outliers; 1,203 MVS points outside
// the proxy, 5,004 in sparse voxels" or the problem.
std::string DescribeClusters(const messages::ClustersContent& content);

}  // namespace avc::cli
