#include "services/clusterer/merge_and_cluster.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace avc::clusterer {

std::string ClustererOptions::Validate() const {
  if (merge.min_points < 1) return "merge.min_points must be at least 1";
  return cluster.Validate();
}

messages::ClustersContent ClusterMerged(merge::MergedPoints merged, int64_t raw_points,
                                        const cluster::ClusterOptions& options,
                                        const std::string& cloud_id, const std::string& map_id) {
  messages::ClustersContent content;
  content.cloud_id = cloud_id;
  content.map_id = map_id;
  content.raw_points = raw_points;
  content.merged = std::move(merged);
  const size_t n = content.merged.size();
  content.clusters.assign(n, cluster::kUnassigned);
  if (n < 3) {
    content.problem = fmt::format(
        "'{}': {} merged points (of {} MVS points) are too few to cluster; are the points inside "
        "the plant proxy?",
        cloud_id, n, raw_points);
    return content;
  }
  cluster::PointSet set;
  set.name = cloud_id;
  set.points = content.merged.cloud.positions;
  set.normals = content.merged.cloud.normals;
  try {
    cluster::ClusterReport report;
    content.clusters = cluster::ClusterPlant(set, options, &report);
    content.num_clusters = static_cast<int32_t>(report.clusters);
  } catch (const std::invalid_argument& error) {
    content.clusters.assign(n, cluster::kUnassigned);
    content.problem =
        fmt::format("clustering the merged points of '{}': {}", cloud_id, error.what());
  }
  return content;
}

messages::ClustersContent MergeAndCluster(const mvs::MvsPoints& points, const mvs::MvsBounds& proxy,
                                          const ClustererOptions& options,
                                          const std::string& cloud_id, const std::string& map_id) {
  merge::MergedPoints merged;
  std::string problem;
  if (points.size() == 0) {
    problem = fmt::format("MVS points '{}' are empty", cloud_id);
  } else if (proxy.empty()) {
    problem = fmt::format("the plant proxy '{}' has no occupied voxel", map_id);
  } else {
    try {
      merged = merge::MergeIntoProxy(points, proxy, options.merge);
    } catch (const std::invalid_argument& error) {
      problem = fmt::format("merging '{}' into '{}': {}", cloud_id, map_id, error.what());
    }
  }
  if (!problem.empty()) {
    messages::ClustersContent content;
    content.cloud_id = cloud_id;
    content.map_id = map_id;
    content.raw_points = static_cast<int64_t>(points.size());
    content.problem = problem;
    return content;
  }
  return ClusterMerged(std::move(merged), static_cast<int64_t>(points.size()), options.cluster,
                       cloud_id, map_id);
}

}  // namespace avc::clusterer
