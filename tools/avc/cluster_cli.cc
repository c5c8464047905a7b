#include "tools/avc/cluster_cli.h"

#include <fmt/format.h>

#include <algorithm>

#include "services/clusterer/clusterer_options.h"

namespace avc::cli {

clusterer::ClustererOptions ClusterFlags::Options() const {
  std::vector<std::string> settings;
  const auto metres = [](double mm) { return config::RealText(mm * 1e-3); };
  if (merge_min_points) settings.push_back(fmt::format("merge.min_points={}", *merge_min_points));
  if (spacing_mm) settings.push_back("cluster.spacing=" + metres(*spacing_mm));
  if (noise_mm) settings.push_back("cluster.noise=" + metres(*noise_mm));
  if (link_factor) settings.push_back("cluster.link_factor=" + config::RealText(*link_factor));
  if (min_cluster_points) {
    settings.push_back(fmt::format("cluster.min_cluster_points={}", *min_cluster_points));
  }
  settings.insert(settings.end(), config.sets.begin(), config.sets.end());
  return clusterer::ClustererOptionTable().Load({}, config.files, settings);
}

void AddClusterFlags(CLI::App* command, ClusterFlags* flags) {
  command->add_option("--merge-min-points", flags->merge_min_points,
                      "MVS points a proxy voxel needs to become a merged point (merge.min_points)");
  command->add_option("--spacing-mm", flags->spacing_mm,
                      "merged point spacing in mm, 0 measured (cluster.spacing, in m)");
  command->add_option("--noise-mm", flags->noise_mm,
                      "point noise in mm, 0 measured (cluster.noise, in m)");
  command->add_option("--link-factor", flags->link_factor,
                      "points closer than this many spacings are neighbours (cluster.link_factor)");
  command->add_option("--min-cluster-points", flags->min_cluster_points,
                      "smallest real cluster, 0 automatic (cluster.min_cluster_points)");
  AddConfigFlags(command, &flags->config,
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
