#pragma once

// Constant-time "is this point inside the plant proxy?" for MVS: the occupied voxel centres of
// an MvsBounds hashed by their grid cell.

#include <Eigen/Core>
#include <cstdint>
#include <unordered_set>

#include "core/mvs/mvs_bounds.h"

namespace avc::mvs {

class OccupancyLookup {
 public:
  // Bounds with no voxels contain every point (no proxy: nothing is ruled out).
  explicit OccupancyLookup(const MvsBounds& bounds);

  // True when p lies in an occupied voxel or within `dilation` voxels of one (Chebyshev).
  bool Contains(const Eigen::Vector3d& p, int dilation = 0) const;
  bool empty() const { return cells_.empty(); }

 private:
  static uint64_t Pack(int64_t x, int64_t y, int64_t z);
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();  // the centre of cell (0, 0, 0)
  double voxel_size_ = 1;
  std::unordered_set<uint64_t> cells_;
};

}  // namespace avc::mvs
