#include "core/cluster/connected_components.h"

#include <algorithm>

namespace avc::cluster {

std::vector<std::vector<uint32_t>> ConnectedComponents(const PointGrid& grid,
                                                       const std::vector<Eigen::Vector3f>& points,
                                                       const std::vector<uint32_t>& subset,
                                                       const LinkRule& link,
                                                       std::vector<int32_t>* scratch) {
  return ComponentsBy(subset, scratch, [&](uint32_t i, const auto& visit) {
    grid.ForEachWithin(points[i], link.radius, [&](uint32_t j) {
      if (link.Linked(points, i, j)) visit(j);
    });
  });
}

}  // namespace avc::cluster
