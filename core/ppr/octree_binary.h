#pragma once

// OctoMap binary (.bt) trees written and read without OctoMap's own readBinary/writeBinaryConst:
// Debian's liboctomap is built with its debug output on, so those print "Reading binary octree
// type OcTree" and " done." to stderr, in the middle of a scan's progress line and of every
// command's output. The header is the one OctoMap writes and reads (its first line, then id,
// size, res and data); the node data goes through OctoMap's silent readBinaryData and
// writeBinaryData, so the bytes are the same as OctoMap's.

#include <octomap/OcTree.h>

#include <memory>
#include <string>

namespace avc::ppr {

// The tree as .bt bytes, byte for byte what OcTree::writeBinaryConst writes.
std::string OctreeBinaryBytes(const octomap::OcTree& tree);

// Reads .bt bytes. Checks the header as OctoMap does (first line, tree type OcTree, a positive
// resolution), then the node data with the depth and length checks that keep corrupt data from
// running away (OctoMap trusts them), and that the node count matches the header. Throws
// std::invalid_argument naming `what` and the problem.
std::unique_ptr<octomap::OcTree> ReadOctreeBinary(const std::string& bytes,
                                                  const std::string& what);

}  // namespace avc::ppr
