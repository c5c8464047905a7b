#include "core/mvs/occupancy_lookup.h"

#include <cmath>

namespace avc::mvs {

OccupancyLookup::OccupancyLookup(const MvsBounds& bounds) : voxel_size_(bounds.voxel_size) {
  if (bounds.empty() || !(voxel_size_ > 0)) return;
  origin_ = bounds.occupied_centres.front().cast<double>();
  cells_.reserve(bounds.occupied_centres.size());
  for (const Eigen::Vector3f& centre : bounds.occupied_centres) {
    const Eigen::Vector3d cell = ((centre.cast<double>() - origin_) / voxel_size_).array().round();
    cells_.insert(Pack(static_cast<int64_t>(cell.x()), static_cast<int64_t>(cell.y()),
                       static_cast<int64_t>(cell.z())));
  }
}

uint64_t OccupancyLookup::Pack(int64_t x, int64_t y, int64_t z) {
  // 21 bits per axis: ±1M voxels, far beyond any plant.
  constexpr int64_t kMask = (int64_t{1} << 21) - 1;
  return (static_cast<uint64_t>(x & kMask) << 42) | (static_cast<uint64_t>(y & kMask) << 21) |
         static_cast<uint64_t>(z & kMask);
}

bool OccupancyLookup::Contains(const Eigen::Vector3d& p, int dilation) const {
  if (cells_.empty()) return true;
  if (!p.allFinite()) return false;
  const Eigen::Vector3d cell = ((p - origin_) / voxel_size_).array().round();
  const int64_t x = static_cast<int64_t>(cell.x());
  const int64_t y = static_cast<int64_t>(cell.y());
  const int64_t z = static_cast<int64_t>(cell.z());
  for (int64_t dx = -dilation; dx <= dilation; ++dx) {
    for (int64_t dy = -dilation; dy <= dilation; ++dy) {
      for (int64_t dz = -dilation; dz <= dilation; ++dz) {
        if (cells_.count(Pack(x + dx, y + dy, z + dz)) != 0) return true;
      }
    }
  }
  return false;
}

}  // namespace avc::mvs
