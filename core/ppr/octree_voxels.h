#pragma once

// The plant proxy as other services receive it: the occupied voxels of its OctoMap tree (a .bt
// file or a voxel_map_t product) on the proxy's own grid, as plain data for model merging.
// Pruned nodes are expanded into the voxels they stand for, and the centres are computed from
// the tree's keys and the exact voxel size (the .bt text keeps only 6 digits of the resolution),
// so they equal PlantProxy::ToMvsBounds() of the proxy that wrote the tree.

#include <cstdint>
#include <string>

#include "core/mvs/mvs_bounds.h"

namespace avc::ppr {

struct OctreeReadOptions {
  // A hostile or corrupt tree could claim a pruned occupied node covering the whole key space;
  // refuse to expand more voxels than this (a 256^3 box is 16.8 million).
  uint64_t max_voxels = 64'000'000;
};

// `bytes`: OctoMap binary (.bt) data. `voxel_size`: the sender's exact resolution; 0 = the
// tree's own (rounded) one. Centres are sorted by voxel index (z, then y, then x). Throws
// std::invalid_argument naming `what` when the bytes do not parse as an OcTree, the tree's depth
// is not 16, the resolutions disagree, or the expansion exceeds max_voxels.
mvs::MvsBounds OccupiedVoxelsFromBinary(const std::string& bytes, double voxel_size,
                                        const std::string& what,
                                        const OctreeReadOptions& options = {});

}  // namespace avc::ppr
