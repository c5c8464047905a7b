#include "core/cluster/neighbour_lists.h"

#include <algorithm>
#include <utility>

namespace avc::cluster {

NeighbourLists::NeighbourLists(const PointGrid& grid, const std::vector<Eigen::Vector3f>& points,
                               const LinkRule& link) {
  offset_.reserve(points.size() + 1);
  offset_.push_back(0);
  std::vector<std::pair<float, uint32_t>> candidates;
  for (size_t p = 0; p < points.size(); ++p) {
    const uint32_t i = static_cast<uint32_t>(p);
    candidates.clear();
    grid.ForEachWithin(points[i], link.radius, [&](uint32_t j) {
      if (j != i && link.Linked(points, i, j)) {
        candidates.emplace_back((points[j] - points[i]).squaredNorm(), j);
      }
    });
    std::sort(candidates.begin(), candidates.end());
    for (const auto& candidate : candidates) neighbour_.push_back(candidate.second);
    offset_.push_back(neighbour_.size());
  }
}

std::vector<std::vector<uint32_t>> ConnectedComponents(const NeighbourLists& neighbours,
                                                       const std::vector<uint32_t>& subset,
                                                       std::vector<int32_t>* scratch) {
  constexpr int32_t kMember = 0;   // in the subset, not reached yet
  constexpr int32_t kReached = 1;  // in the subset, already in a component
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
      for (const uint32_t* j = neighbours.begin(i); j != neighbours.end(i); ++j) {
        if (mark[*j] != kMember) continue;
        mark[*j] = kReached;
        component.push_back(*j);
        frontier.push_back(*j);
      }
    }
    std::sort(component.begin(), component.end());
    components.push_back(std::move(component));
  }
  for (uint32_t i : subset) mark[i] = -1;
  return components;
}

}  // namespace avc::cluster
