#include "core/cluster/divfrp.h"

#include <algorithm>
#include <utility>

namespace avc::cluster {

std::vector<std::vector<uint32_t>> SplitByFurthestReference(
    const NeighbourLists& neighbours, const std::vector<Eigen::Vector3f>& points,
    const std::vector<uint32_t>& cluster, float link_radius, std::vector<int32_t>* scratch) {
  if (cluster.size() < 2) return {};
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (uint32_t i : cluster) centroid += points[i].cast<double>();
  centroid /= static_cast<double>(cluster.size());
  uint32_t reference = cluster[0];
  double furthest = -1.0;
  for (uint32_t i : cluster) {
    const double d = (points[i].cast<double>() - centroid).squaredNorm();
    if (d > furthest) {
      furthest = d;
      reference = i;
    }
  }
  std::vector<std::pair<double, uint32_t>> order;
  order.reserve(cluster.size());
  for (uint32_t i : cluster) order.emplace_back((points[i] - points[reference]).norm(), i);
  std::sort(order.begin(), order.end());
  double widest = 0.0;
  size_t cut = 0;
  for (size_t k = 0; k + 1 < order.size(); ++k) {
    const double gap = order[k + 1].first - order[k].first;
    if (gap > widest) {
      widest = gap;
      cut = k + 1;
    }
  }
  std::vector<std::vector<uint32_t>> groups;
  if (widest > link_radius) {
    groups.resize(2);
    for (size_t k = 0; k < order.size(); ++k) groups[k < cut ? 0 : 1].push_back(order[k].second);
  } else {
    std::vector<std::vector<uint32_t>> components =
        ConnectedComponents(neighbours, cluster, scratch);
    if (components.size() < 2) return {};
    groups.resize(2);
    for (auto& component : components) {
      const bool holds_reference =
          std::binary_search(component.begin(), component.end(), reference);
      auto& group = groups[holds_reference ? 0 : 1];
      group.insert(group.end(), component.begin(), component.end());
    }
  }
  for (auto& group : groups) std::sort(group.begin(), group.end());
  return groups;
}

}  // namespace avc::cluster
