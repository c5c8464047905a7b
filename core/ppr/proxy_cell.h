#pragma once

// The unit of the proxy's sparse hierarchy: an octree-aligned cube over which every view so far
// cast the same vote, so its counts hold for each voxel inside it.

#include <cstdint>

namespace avc::ppr {

enum class VoxelState : uint8_t { kUnknown, kFree, kOccupied };

struct ProxyCell {
  // Minimum corner in units of the cell's own edge (2^level voxels): the cell spans voxels
  // [x * 2^level, (x + 1) * 2^level) along x, likewise y and z.
  int32_t x = 0, y = 0, z = 0;
  int32_t level = 0;  // 0 = one voxel
  uint16_t background_votes = 0;
  uint16_t plant_votes = 0;
};

// Child `i` of a cell uses OctoMap's child order: bit 0 x, bit 1 y, bit 2 z.
inline ProxyCell ChildCell(const ProxyCell& parent, int i) {
  ProxyCell child = parent;
  child.level = parent.level - 1;
  child.x = 2 * parent.x + (i & 1);
  child.y = 2 * parent.y + ((i >> 1) & 1);
  child.z = 2 * parent.z + ((i >> 2) & 1);
  return child;
}

inline int ChildIndex(const ProxyCell& cell) {
  return (cell.x & 1) | ((cell.y & 1) << 1) | ((cell.z & 1) << 2);
}

}  // namespace avc::ppr
