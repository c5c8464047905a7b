#pragma once

// Mirrors the proxy's cells in an OctoMap OcTree: occupied cells become occupied nodes, the rest
// of the box free nodes, unknown cells and everything outside the box stay absent. The result is
// fully pruned, so it depends only on the voxel states, not on how the cells were split.

#include <octomap/OcTree.h>

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "core/ppr/proxy_cell.h"

namespace avc::ppr {

struct OctreeSource {
  const std::vector<ProxyCell>* cells = nullptr;    // not-free space, depth-first order
  const std::vector<VoxelState>* states = nullptr;  // per cell: kOccupied or kUnknown
  Eigen::Array3i box_begin, box_end;                // voxel index range [begin, end)
  int top_level = 0;                                // level of the cells the box is tiled with
  double voxel_size = 0;
};

// OctoMap's key of voxel index i is i + 32768, so indices must lie in [-32768, 32768).
constexpr int kOctreeKeyOffset = 32768;
constexpr int kOctreeDepth = 16;

std::unique_ptr<octomap::OcTree> BuildProxyOctree(const OctreeSource& source);

// Cells of the tiling at `top_level` that overlap [begin, end), in the proxy's order (z, y, x).
// Calls visit(tx, ty, tz) for each.
template <class Visit>
void ForEachTopCell(const Eigen::Array3i& begin, const Eigen::Array3i& end, int top_level,
                    Visit&& visit) {
  const auto floor_shift = [&](int v) { return v >> top_level; };  // arithmetic: floor
  const auto ceil_shift = [&](int v) { return -((-v) >> top_level); };
  for (int tz = floor_shift(begin.z()); tz < ceil_shift(end.z()); ++tz) {
    for (int ty = floor_shift(begin.y()); ty < ceil_shift(end.y()); ++ty) {
      for (int tx = floor_shift(begin.x()); tx < ceil_shift(end.x()); ++tx) visit(tx, ty, tz);
    }
  }
}

}  // namespace avc::ppr
