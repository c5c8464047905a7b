#pragma once

// Where the plant can be: the occupied voxels of the plant proxy (PPR). MVS uses it to bound
// its depth search and to drop points outside the plant; kept as plain data so that MVS does
// not depend on the carving code.

#include <Eigen/Core>
#include <vector>

namespace avc::mvs {

struct MvsBounds {
  std::vector<Eigen::Vector3f> occupied_centres;  // world, metres
  double voxel_size = 0;                          // edge length of every voxel, metres

  bool empty() const { return occupied_centres.empty(); }
};

}  // namespace avc::mvs
