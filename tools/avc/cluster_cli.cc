#include "tools/avc/cluster_cli.h"

#include <fmt/format.h>

#include <algorithm>

#include "services/clusterer/clusterer_options.h"

namespace avc::cli {

clusterer::ClustererOptions ClusterFlags::Options() const {
  return LoadOptions(clusterer::ClustererOptionTable(), config);
}

void AddClusterFlags(CLI::App* command, ClusterFlags* flags) {
  ConfigFlags* config = &flags->config;
  AddShorthand(command, config, "--merge-min-points", "merge.min_points",
               "MVS points a proxy voxel needs to become a merged point");
  AddScaledShorthand(command, config, "--spacing-mm", "cluster.spacing", 1e-3,
                     "merged point spacing in mm, 0 measured");
  AddScaledShorthand(command, config, "--noise-mm", "cluster.noise", 1e-3,
                     "point noise in mm, 0 measured");
  AddShorthand(command, config, "--link-factor", "cluster.link_factor",
               "points closer than this many spacings are neighbours");
  AddShorthand(command, config, "--min-cluster-points", "cluster.min_cluster_points",
               "smallest real cluster, 0 automatic");
  AddConfigFlags(command, config,
                 clusterer::ClustererOptionTable().Reference(clusterer::ClustererOptions{}));
}

std::string DescribeClusters(const messages::ClustersContent& content) {
  if (!content.problem.empty()) return "clusters: none; " + content.problem;
  const auto outliers =
      std::count(content.clusters.begin(), content.clusters.end(), cluster::kUnassigned);
  return fmt::format(
      "clusters: {} merged points (of {} MVS points) in {} clusters, {} outliers; {} MVS points "
      "outside the proxy, {} in voxels with too few",
      content.merged.size(), content.raw_points, content.num_clusters, outliers,
      content.merged.outside_proxy, content.merged.in_sparse_voxels);
}

}  // namespace avc::cli
