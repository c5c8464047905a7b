#include "core/ppr/octree_voxels.h"

#include <fmt/format.h>
#include <octomap/OcTree.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "core/ppr/octree_binary.h"
#include "core/ppr/proxy_octree.h"

namespace avc::ppr {

mvs::MvsBounds OccupiedVoxelsFromBinary(const std::string& bytes, double voxel_size,
                                        const std::string& what, const OctreeReadOptions& options) {
  if (!(voxel_size >= 0) || !std::isfinite(voxel_size)) {
    throw std::invalid_argument(fmt::format("{}: voxel size {} is not usable", what, voxel_size));
  }
  const std::unique_ptr<octomap::OcTree> read = ReadOctreeBinary(bytes, what);
  const octomap::OcTree& tree = *read;
  if (tree.getTreeDepth() != kOctreeDepth) {
    throw std::invalid_argument(fmt::format("{}: octree depth {} (the plant proxy's is {})", what,
                                            tree.getTreeDepth(), kOctreeDepth));
  }
  const double resolution = voxel_size > 0 ? voxel_size : tree.getResolution();
  // .bt writes the resolution with 6 significant digits.
  if (!(resolution > 0) || std::abs(tree.getResolution() - resolution) > 1e-5 * resolution) {
    throw std::invalid_argument(fmt::format("{}: the tree's resolution {} is not the voxel size {}",
                                            what, tree.getResolution(), resolution));
  }

  std::vector<std::tuple<int, int, int>> voxels;  // (z, y, x): sorts in the documented order
  uint64_t total = 0;
  for (auto it = tree.begin_leafs(); it != tree.end_leafs(); ++it) {
    if (!tree.isNodeOccupied(*it)) continue;
    const int span = 1 << (tree.getTreeDepth() - it.getDepth());
    total += static_cast<uint64_t>(span) * span * span;
    if (total > options.max_voxels) {
      throw std::invalid_argument(
          fmt::format("{}: more than {} occupied voxels; refusing to expand the tree", what,
                      options.max_voxels));
    }
    const octomap::OcTreeKey corner = it.getIndexKey();
    const int x0 = corner[0] - kOctreeKeyOffset;
    const int y0 = corner[1] - kOctreeKeyOffset;
    const int z0 = corner[2] - kOctreeKeyOffset;
    for (int z = z0; z < z0 + span; ++z) {
      for (int y = y0; y < y0 + span; ++y) {
        for (int x = x0; x < x0 + span; ++x) voxels.emplace_back(z, y, x);
      }
    }
  }
  std::sort(voxels.begin(), voxels.end());
  mvs::MvsBounds bounds;
  bounds.voxel_size = resolution;
  bounds.occupied_centres.reserve(voxels.size());
  for (const auto& [z, y, x] : voxels) {
    bounds.occupied_centres.emplace_back(static_cast<float>((x + 0.5) * resolution),
                                         static_cast<float>((y + 0.5) * resolution),
                                         static_cast<float>((z + 0.5) * resolution));
  }
  return bounds;
}

}  // namespace avc::ppr
