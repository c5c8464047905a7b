#pragma once

// A uniform grid over a point cloud for fixed-radius neighbour queries (the clustering's only
// spatial index: every radius it asks for is a small multiple of the point spacing, so one cell
// size serves all queries and a tree is not needed).

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace avc::cluster {

class PointGrid {
 public:
  // cell_size > 0 (metres). Points must be finite. When the bounding box would need too many
  // cells (sparse outliers far away), the cell size grows so the grid stays small; queries stay
  // exact.
  PointGrid(const std::vector<Eigen::Vector3f>& points, float cell_size);

  float cell_size() const { return cell_size_; }

  // Calls visit(j) for every point j with |points[j] - p| <= radius, in ascending cell order
  // (deterministic). radius may exceed the cell size (more cells are scanned).
  template <class Visit>
  void ForEachWithin(const Eigen::Vector3f& p, float radius, Visit&& visit) const {
    const int reach = static_cast<int>(std::ceil(radius / cell_size_));
    const Eigen::Vector3i c = CellOf(p);
    const float r2 = radius * radius;
    for (int z = std::max(0, c.z() - reach); z <= std::min(dims_.z() - 1, c.z() + reach); ++z) {
      for (int y = std::max(0, c.y() - reach); y <= std::min(dims_.y() - 1, c.y() + reach); ++y) {
        const int x0 = std::max(0, c.x() - reach);
        const int x1 = std::min(dims_.x() - 1, c.x() + reach);
        const size_t row = (static_cast<size_t>(z) * dims_.y() + y) * dims_.x();
        for (size_t k = cell_start_[row + x0]; k < cell_start_[row + x1 + 1]; ++k) {
          const uint32_t j = order_[k];
          if ((points_[j] - p).squaredNorm() <= r2) visit(j);
        }
      }
    }
  }

 private:
  Eigen::Vector3i CellOf(const Eigen::Vector3f& p) const;

  const std::vector<Eigen::Vector3f>& points_;
  float cell_size_;
  Eigen::Vector3f origin_;
  Eigen::Vector3i dims_;
  std::vector<uint32_t> cell_start_;  // per cell (x fastest), plus one end marker
  std::vector<uint32_t> order_;       // point indices sorted by cell, ascending within a cell
};

}  // namespace avc::cluster
