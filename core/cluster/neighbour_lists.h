#pragma once

// Every point's same-surface neighbours within the link radius, nearest first: computed once per
// cloud so the neck test can take any cluster's k-nearest-neighbour graph without new searches.

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/cluster/connected_components.h"
#include "core/cluster/point_grid.h"

namespace avc::cluster {

class NeighbourLists {
 public:
  // Neighbours j != i with |p_j - p_i| <= link.radius and link.Linked(i, j), sorted by distance,
  // ties by index (deterministic).
  NeighbourLists(const PointGrid& grid, const std::vector<Eigen::Vector3f>& points,
                 const LinkRule& link);

  const uint32_t* begin(uint32_t i) const { return neighbour_.data() + offset_[i]; }
  const uint32_t* end(uint32_t i) const { return neighbour_.data() + offset_[i + 1]; }

 private:
  std::vector<size_t> offset_;  // points + 1 entries
  std::vector<uint32_t> neighbour_;
};

// The same components as ConnectedComponents with the lists' grid and link rule (each sorted,
// ordered by smallest index), without searching the grid again. scratch as there.
std::vector<std::vector<uint32_t>> ConnectedComponents(const NeighbourLists& neighbours,
                                                       const std::vector<uint32_t>& subset,
                                                       std::vector<int32_t>* scratch);

}  // namespace avc::cluster
