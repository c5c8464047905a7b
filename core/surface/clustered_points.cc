#include "core/surface/clustered_points.h"

#include <fmt/format.h>

#include <map>
#include <stdexcept>

#include "core/cluster/point_set.h"

namespace avc::surface {

ClusterMembers GroupByCluster(const ClusteredPoints& input, std::vector<std::string>* warnings) {
  const geometry::PointCloud& cloud = input.cloud;
  if (input.clusters.size() != cloud.size()) {
    throw std::invalid_argument(
        fmt::format("surface input: {} cluster ids for {} points (need one per point)",
                    input.clusters.size(), cloud.size()));
  }
  if (!cloud.normals.empty() && cloud.normals.size() != cloud.size()) {
    throw std::invalid_argument(
        fmt::format("surface input: {} normals for {} points", cloud.normals.size(), cloud.size()));
  }
  if (!cloud.colors.empty() && cloud.colors.size() != cloud.size()) {
    throw std::invalid_argument(
        fmt::format("surface input: {} colours for {} points", cloud.colors.size(), cloud.size()));
  }
  std::map<int32_t, std::vector<uint32_t>> groups;
  size_t non_finite = 0;
  size_t first_non_finite = 0;
  for (size_t i = 0; i < cloud.size(); ++i) {
    const int32_t id = input.clusters[i];
    if (id < cluster::kUnassigned) {
      throw std::invalid_argument(fmt::format(
          "surface input: point {} has cluster id {} (ids are >= 0, or -1 for unassigned)", i, id));
    }
    if (id == cluster::kUnassigned) continue;
    const bool finite =
        cloud.positions[i].allFinite() && (cloud.normals.empty() || cloud.normals[i].allFinite());
    if (!finite) {
      if (non_finite++ == 0) first_non_finite = i;
      continue;
    }
    groups[id].push_back(static_cast<uint32_t>(i));
  }
  if (non_finite > 0 && warnings != nullptr) {
    warnings->push_back(fmt::format(
        "surface input: {} point(s) with a non-finite position or normal left out (first: point "
        "{})",
        non_finite, first_non_finite));
  }
  ClusterMembers members;
  for (auto& [id, points] : groups) {
    members.ids.push_back(id);
    members.points.push_back(std::move(points));
  }
  return members;
}

}  // namespace avc::surface
