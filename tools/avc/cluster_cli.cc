#include "tools/avc/cluster_cli.h"

#include <fmt/format.h>

#include <algorithm>

namespace avc::cli {

clusterer::ClustererOptions ClusterFlags::Options() const {
  clusterer::ClustererOptions options;
  options.merge.min_points = merge_min_points;
  options.cluster.spacing = spacing_mm * 1e-3;
  options.cluster.noise = noise_mm * 1e-3;
  options.cluster.link_factor = link_factor;
  options.cluster.min_cluster_points = min_cluster_points;
  return options;
}

void AddClusterFlags(CLI::App* command, ClusterFlags* flags) {
  command
      ->add_option("--merge-min-points", flags->merge_min_points,
                   "MVS points a proxy voxel needs to become a merged point (paper: more than 3)")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  command
      ->add_option("--spacing-mm", flags->spacing_mm,
                   "merged point spacing in mm (0: the median nearest-neighbour distance)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1000.0));
  command
      ->add_option("--noise-mm", flags->noise_mm,
                   "point noise in mm (0: the median local plane residual)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1000.0));
  command
      ->add_option("--link-factor", flags->link_factor,
                   "points closer than this many spacings are neighbours")
      ->capture_default_str()
      ->check(CLI::Range(1.0, 100.0));
  command
      ->add_option("--min-cluster-points", flags->min_cluster_points,
                   "smallest real cluster (0: automatic, 13)")
      ->capture_default_str()
      ->check(CLI::Range(0, 1000000));
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
