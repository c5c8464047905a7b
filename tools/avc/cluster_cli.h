#pragma once

// Clustering on the command line (`avc cluster`, `avc clusterer`): --config / --set over the
// clusterer's options (services/clusterer/clusterer_options.h), shorthand flags for the main
// ones (the data scales, measured when 0, and the main thresholds of Algorithm 2;
// core/cluster/cluster_plant.h explains each), and the one-line summary of a result.

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "services/clusterer/merge_and_cluster.h"
#include "tools/avc/config_flags.h"

namespace avc::cli {

struct ClusterFlags {
  ConfigFlags config;  // with the shorthands --merge-min-points, --spacing-mm, ...

  // The defaults, then --config, the shorthands given, --set. Throws config::ConfigError.
  clusterer::ClustererOptions Options() const;
};

void AddClusterFlags(CLI::App* command, ClusterFlags* flags);

// "clusters: 9,153 merged points (of 80,095) in 14 clusters, 12 outliers; 1,203 MVS points outside
// the proxy, 5,004 in sparse voxels" or the problem.
std::string DescribeClusters(const messages::ClustersContent& content);

}  // namespace avc::cli
