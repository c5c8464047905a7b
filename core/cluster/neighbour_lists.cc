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
  return ComponentsBy(subset, scratch, [&](uint32_t i, const auto& visit) {
    for (const uint32_t* j = neighbours.begin(i); j != neighbours.end(i); ++j) visit(*j);
  });
}

}  // namespace avc::cluster
