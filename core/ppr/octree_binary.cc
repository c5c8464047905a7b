#include "core/ppr/octree_binary.h"

#include <fmt/format.h>

#include <sstream>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "core/ppr/proxy_octree.h"

namespace avc::ppr {
namespace {

// The first line of every .bt file (OctoMap keeps its copy protected).
constexpr std::string_view kFirstLine = "# Octomap OcTree binary file";

// The header values OctoMap's reader takes, and where the node data starts.
struct BinaryHeader {
  std::string id;
  double resolution = 0;
  size_t nodes = 0;
  size_t data_offset = std::string::npos;  // npos: no "data" line
};

// As OctoMap's header reader: after the first line, whitespace-separated tokens; "#" and
// unknown keywords skip their line, id, res and size take a value, and "data" ends the header
// with its line.
BinaryHeader ReadHeader(const std::string& bytes) {
  BinaryHeader header;
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
      header.data_offset = s.good() ? static_cast<size_t>(s.tellg()) : bytes.size();
      return header;
    }
    if (token == "id") {
      s >> header.id;
    } else if (token == "res") {
      s >> header.resolution;
    } else if (token == "size") {
      s >> header.nodes;
    } else {
      skip_line();  // a comment or an unknown keyword
    }
  }
  return header;
}

// What is wrong with the node data (after the "data" line), or empty. Each node is two bytes
// of child bits (two per child: 01 occupied leaf, 10 free leaf, 11 inner), depth first, each
// inner child's node following at once. OctoMap's readBinaryData trusts them: data cut short or
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

}  // namespace

std::string OctreeBinaryBytes(const octomap::OcTree& tree) {
  std::ostringstream out;
  // The header exactly as OctoMap's writeBinaryConst puts it (default stream precision).
  out << kFirstLine
      << "\n# (feel free to add / change comments, but leave the first line as it is!)\n#\n";
  out << "id " << tree.getTreeType() << "\n";
  out << "size " << tree.size() << "\n";
  out << "res " << tree.getResolution() << "\n";
  out << "data\n";
  tree.writeBinaryData(out);
  if (!out) throw std::runtime_error("OctoMap could not serialise the octree");
  return out.str();
}

std::unique_ptr<octomap::OcTree> ReadOctreeBinary(const std::string& bytes,
                                                  const std::string& what) {
  const BinaryHeader header = ReadHeader(bytes);
  if (bytes.compare(0, kFirstLine.size(), kFirstLine) != 0 ||
      header.data_offset == std::string::npos) {
    throw std::invalid_argument(what + ": not an OctoMap binary (.bt) tree");
  }
  auto tree = std::make_unique<octomap::OcTree>(0.1);
  if (header.id != tree->getTreeType() || !(header.resolution > 0)) {
    throw std::invalid_argument(
        fmt::format("{}: not an OctoMap binary (.bt) OcTree (type '{}', resolution {})", what,
                    header.id, header.resolution));
  }
  const std::string_view data = std::string_view(bytes).substr(header.data_offset);
  if (header.nodes > 0) {
    if (const std::string problem = NodeDataProblem(data); !problem.empty()) {
      throw std::invalid_argument(what + ": not a usable OctoMap binary (.bt) tree: " + problem);
    }
  }
  tree->setResolution(header.resolution);
  if (header.nodes > 0) {
    std::istringstream stream{std::string(data)};
    tree->readBinaryData(stream);
  }
  if (tree->size() != header.nodes) {
    throw std::invalid_argument(fmt::format("{}: the tree holds {} nodes, its header says {}", what,
                                            tree->size(), header.nodes));
  }
  return tree;
}

}  // namespace avc::ppr
