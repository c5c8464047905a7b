#pragma once

// Where the plant can be: the occupied voxels of the plant proxy (PPR). MVS uses it to bound
// its depth search and to drop points outside the plant; kept as plain data so that MVS does
// not depend on the carving code.

#include <Eigen/Core>
#include <algorithm>
#include <optional>
#include <vector>

namespace avc::mvs {

struct MvsBounds {
  std::vector<Eigen::Vector3f> occupied_centres;  // world, metres
  double voxel_size = 0;                          // edge length of every voxel, metres

  bool empty() const { return occupied_centres.empty(); }

  // The centre height of the lowest occupied voxels (m, world z); nullopt when empty.
  std::optional<float> LowestCentreZ() const {
    if (empty()) return std::nullopt;
    float lowest = occupied_centres.front().z();
    for (const Eigen::Vector3f& centre : occupied_centres) lowest = std::min(lowest, centre.z());
    return lowest;
  }
  // The bottom face of the lowest occupied voxels (m, world z); nullopt when empty.
  std::optional<double> BottomZ() const {
    const std::optional<float> lowest = LowestCentreZ();
    if (!lowest) return std::nullopt;
    return static_cast<double>(*lowest) - 0.5 * voxel_size;
  }
};

}  // namespace avc::mvs
