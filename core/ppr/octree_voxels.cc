#include "core/ppr/octree_voxels.h"

#include <fmt/format.h>
#include <octomap/OcTree.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "core/ppr/proxy_octree.h"

namespace avc::ppr {
namespace {

// What is wrong with the node data of a .bt file (after its "data" line), or empty. Each node is
// two bytes of child bits (two per child: 01 occupied leaf, 10 free leaf, 11 inner), depth first,
// each inner child's node following at once. OctoMap's readBinary trusts them: data cut short or
// an inner child below the deepest level makes it read past the end and build nodes without
// bound (found by fuzz/voxel_map). Walking the bits first bounds the work by the bytes.
std::string NodeDataProblem(std::string_view data) {
  std::vector<int> pending = {0};  // depths of the nodes still to read, next on top
  size_t at = 0;
  while (!pending.empty()) {
    const int depth = pending.back();
    pending.pop_back();
    if (at + 2 > data.size()) return "its node data ends inside the tree";
    const auto first = static_cast<uint8_t>(data[at]);
    const auto second = static_cast<uint8_t>(data[at + 1]);
    at += 2;
    // Children are read in order 1..8: push 8..1 so child 1 comes off the stack first.
    for (int child = 7; child >= 0; --child) {
      const uint8_t bits = child < 4 ? first : second;
      const int shift = 2 * (child % 4);
      if (((bits >> shift) & 3) != 3) continue;
      if (depth + 1 > kOctreeDepth) return "it has nodes below the octree's deepest level";
      pending.push_back(depth + 1);
    }
  }
  return {};
}

// Where OctoMap's readBinary starts reading nodes, as its header reader finds it: after the
// first line, whitespace-separated tokens; "#" and unknown keywords skip their line, id, res and
// size take a value, and "data" ends the header with its line. npos when it finds no "data".
size_t NodeDataOffset(const std::string& bytes) {
  std::istringstream s(bytes);
  std::string line;
  std::getline(s, line);
  const auto skip_line = [&s] {
    while (s.good() && s.get() != '\n') {
    }
  };
  std::string token;
  while (s.good()) {
    if (!(s >> token)) break;
    if (token == "data") {
      skip_line();
      return s.good() ? static_cast<size_t>(s.tellg()) : bytes.size();
    }
    if (token == "id") {
      std::string id;
      s >> id;
    } else if (token == "res") {
      double res = 0;
      s >> res;
    } else if (token == "size") {
      unsigned size = 0;
      s >> size;
    } else {
      skip_line();  // a comment or an unknown keyword
    }
  }
  return std::string::npos;
}

}  // namespace

mvs::MvsBounds OccupiedVoxelsFromBinary(const std::string& bytes, double voxel_size,
                                        const std::string& what, const OctreeReadOptions& options) {
  if (!(voxel_size >= 0) || !std::isfinite(voxel_size)) {
    throw std::invalid_argument(fmt::format("{}: voxel size {} is not usable", what, voxel_size));
  }
  const size_t data = NodeDataOffset(bytes);
  if (data == std::string::npos) {
    throw std::invalid_argument(what + ": not an OctoMap binary (.bt) tree");
  }
  if (const std::string problem = NodeDataProblem(std::string_view(bytes).substr(data));
      !problem.empty()) {
    throw std::invalid_argument(what + ": not a usable OctoMap binary (.bt) tree: " + problem);
  }
  std::istringstream stream(bytes);
  octomap::OcTree tree(0.1);
  if (!tree.readBinary(stream)) {
    throw std::invalid_argument(what + ": not an OctoMap binary (.bt) tree");
  }
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
