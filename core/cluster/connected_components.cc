#include "core/cluster/connected_components.h"

#include <algorithm>

namespace avc::cluster {
namespace {
constexpr int32_t kMember = 0;   // in the subset, not reached yet
constexpr int32_t kReached = 1;  // in the subset, already in a component
}  // namespace

std::vector<std::vector<uint32_t>> ConnectedComponents(const PointGrid& grid,
                                                       const std::vector<Eigen::Vector3f>& points,
                                                       const std::vector<uint32_t>& subset,
                                                       const LinkRule& link,
                                                       std::vector<int32_t>* scratch) {
  std::vector<int32_t>& mark = *scratch;
  for (uint32_t i : subset) mark[i] = kMember;
  std::vector<uint32_t> sorted = subset;
  std::sort(sorted.begin(), sorted.end());
  std::vector<std::vector<uint32_t>> components;
  std::vector<uint32_t> frontier;
  for (uint32_t seed : sorted) {
    if (mark[seed] != kMember) continue;
    std::vector<uint32_t> component{seed};
    mark[seed] = kReached;
    frontier.assign(1, seed);
    while (!frontier.empty()) {
      const uint32_t i = frontier.back();
      frontier.pop_back();
      grid.ForEachWithin(points[i], link.radius, [&](uint32_t j) {
        if (mark[j] != kMember || !link.Linked(points, i, j)) return;
        mark[j] = kReached;
        component.push_back(j);
        frontier.push_back(j);
      });
    }
    std::sort(component.begin(), component.end());
    components.push_back(std::move(component));
  }
  for (uint32_t i : subset) mark[i] = -1;
  return components;
}

}  // namespace avc::cluster
