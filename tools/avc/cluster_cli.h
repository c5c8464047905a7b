#pragma once

// Clustering on the command line (`avc cluster`, `avc clusterer`): --config / --set over the
// clusterer's options (services/clusterer/clusterer_options.h), shorthand flags for the main
// ones (the data scales, measured when 0, and the main thresholds of Algorithm 2;
// core/cluster/cluster_plant.h explains each), and the one-line summary of a result.

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "services/clusterer/merge_and_cluster.h"
#include "tools/avc/config_flags.h"

namespace avc::cli {

struct ClusterFlags {
  std::optional<double> spacing_mm;       // cluster.spacing (m)
  std::optional<double> noise_mm;         // cluster.noise (m)
  std::optional<double> link_factor;      // cluster.link_factor
  std::optional<int> min_cluster_points;  // cluster.min_cluster_points
  std::optional<int> merge_min_points;    // merge.min_points
  ConfigFlags config;

  // The defaults, then --config, the shorthands given, --set. Throws config::ConfigError.
  clusterer::ClustererOptions Options() const;
};

void AddClusterFlags(CLI::App* command, ClusterFlags* flags);

// "clusters: 9,153 merged points (of 80,095) in 14 clusters, 12 outliers; 1,203 MVS points outside
// the proxy, 5,004 in sparse voxels" or the problem.
std::string DescribeClusters(const messages::ClustersContent& content);

}  // namespace avc::cli
