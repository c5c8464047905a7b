#include "core/ppr/proxy_octree.h"

#include <array>

namespace avc::ppr {
namespace {

// OcTree with a way to create its root: OctoMap only grows a root through updateNode, which
// always descends to full depth, and the proxy inserts whole cells at coarse depths.
class RootedOcTree : public octomap::OcTree {
 public:
  using octomap::OcTree::OcTree;
  octomap::OcTreeNode* CreateRoot() {
    if (root == nullptr) {
      root = new octomap::OcTreeNode();
      ++tree_size;
      size_changed = true;
    }
    return root;
  }
};

struct Region {
  int x, y, z, level;
};

bool Contains(const Region& outer, const ProxyCell& cell) {
  const int shift = outer.level - cell.level;
  return shift >= 0 && (cell.x >> shift) == outer.x && (cell.y >> shift) == outer.y &&
         (cell.z >> shift) == outer.z;
}

class Builder {
 public:
  Builder(const OctreeSource& source, RootedOcTree& tree) : source_(source), tree_(tree) {}

  // True when every voxel of `region` inside the box is an unknown cell of [begin, end): such a
  // region gets no node (OctoMap cannot free a node's emptied child array, so none is made).
  bool AllUnknown(const Region& region, size_t begin, size_t end) const {
    const auto& cells = *source_.cells;
    const Eigen::Array3i lo = Eigen::Array3i(region.x, region.y, region.z) * (1 << region.level);
    const Eigen::Array3i hi = lo + (1 << region.level);
    const Eigen::Array3i overlap = (hi.min(source_.box_end) - lo.max(source_.box_begin)).max(0);
    const uint64_t in_box = uint64_t(overlap.x()) * uint64_t(overlap.y()) * uint64_t(overlap.z());
    uint64_t unknown = 0;
    for (size_t i = begin; i < end; ++i) {
      if ((*source_.states)[i] != VoxelState::kOccupied)
        unknown += uint64_t{1} << (3 * cells[i].level);
    }
    return unknown == in_box;
  }

  // Fills `node` for `region` from cells [begin, end); the region holds some known voxel.
  void Fill(octomap::OcTreeNode* node, const Region& region, size_t begin, size_t end) {
    const auto& cells = *source_.cells;
    if (begin == end && BoxOverlap(region) == kInside) {
      node->setLogOdds(tree_.getClampingThresMinLog());
      return;
    }
    if (end - begin == 1 && cells[begin].level == region.level) {
      node->setLogOdds(tree_.getClampingThresMaxLog());  // the only known cell state left
      return;
    }
    size_t cursor = begin;
    for (int i = 0; i < 8; ++i) {
      const Region child{2 * region.x + (i & 1), 2 * region.y + ((i >> 1) & 1),
                         2 * region.z + ((i >> 2) & 1), region.level - 1};
      const size_t child_begin = cursor;
      while (cursor < end && Contains(child, cells[cursor])) ++cursor;
      if (AllUnknown(child, child_begin, cursor)) continue;
      Fill(tree_.createNodeChild(node, i), child, child_begin, cursor);
    }
    tree_.pruneNode(node);  // collapses eight equal leaves into one
  }

  // Merges equal siblings above the top level, where the tiles meet.
  void PruneAbove(octomap::OcTreeNode* node, int depth, int top_depth) {
    if (depth >= top_depth || !tree_.nodeHasChildren(node)) return;
    for (unsigned i = 0; i < 8; ++i) {
      if (tree_.nodeChildExists(node, i)) {
        PruneAbove(tree_.getNodeChild(node, i), depth + 1, top_depth);
      }
    }
    if (depth > 0) tree_.pruneNode(node);
  }

 private:
  enum { kOutside, kPartial, kInside };
  int BoxOverlap(const Region& region) const {
    const Eigen::Array3i lo = Eigen::Array3i(region.x, region.y, region.z) * (1 << region.level);
    const Eigen::Array3i hi = lo + (1 << region.level);
    if ((hi <= source_.box_begin).any() || (lo >= source_.box_end).any()) return kOutside;
    if ((lo >= source_.box_begin).all() && (hi <= source_.box_end).all()) return kInside;
    return kPartial;
  }

  const OctreeSource& source_;
  RootedOcTree& tree_;
};

}  // namespace

std::unique_ptr<octomap::OcTree> BuildProxyOctree(const OctreeSource& source) {
  auto tree = std::make_unique<RootedOcTree>(source.voxel_size);
  octomap::OcTreeNode* root = tree->CreateRoot();
  Builder builder(source, *tree);
  const auto& cells = *source.cells;
  const int top_depth = kOctreeDepth - source.top_level;
  size_t cursor = 0;
  ForEachTopCell(source.box_begin, source.box_end, source.top_level, [&](int tx, int ty, int tz) {
    const Region top{tx, ty, tz, source.top_level};
    const size_t begin = cursor;
    while (cursor < cells.size() && Contains(top, cells[cursor])) ++cursor;
    if (builder.AllUnknown(top, begin, cursor)) return;
    // Walk from the root to the tile's node, creating the path.
    const std::array<int, 3> key{(tx << source.top_level) + kOctreeKeyOffset,
                                 (ty << source.top_level) + kOctreeKeyOffset,
                                 (tz << source.top_level) + kOctreeKeyOffset};
    octomap::OcTreeNode* node = root;
    for (int depth = 0; depth < top_depth; ++depth) {
      const int bit = kOctreeDepth - 1 - depth;
      const unsigned child =
          ((key[0] >> bit) & 1) | (((key[1] >> bit) & 1) << 1) | (((key[2] >> bit) & 1) << 2);
      node = tree->nodeChildExists(node, child) ? tree->getNodeChild(node, child)
                                                : tree->createNodeChild(node, child);
    }
    builder.Fill(node, top, begin, cursor);
  });
  // A root without children would read as one unknown-valued leaf: an empty tree says unknown.
  if (!tree->nodeHasChildren(root)) {
    tree->clear();
    return tree;
  }
  builder.PruneAbove(root, 0, top_depth);
  tree->updateInnerOccupancy();
  return tree;
}

}  // namespace avc::ppr
