#include "core/ppr/octree_binary.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

namespace avc::ppr {
namespace {

// A small tree with occupied, free and pruned parts.
octomap::OcTree SampleTree() {
  octomap::OcTree tree(0.00252);
  tree.updateNode(octomap::point3d(0.01f, 0.02f, 0.03f), true);
  tree.updateNode(octomap::point3d(-0.01f, 0.0f, 0.05f), false);
  for (float x : {0.0005f, 0.0030f}) {
    for (float y : {0.0005f, 0.0030f}) {
      for (float z : {0.0005f, 0.0030f}) tree.updateNode(octomap::point3d(x, y, z), true);
    }
  }
  tree.prune();
  return tree;
}

std::string OctoMapBytes(const octomap::OcTree& tree) {
  std::ostringstream out;
  tree.writeBinaryConst(out);
  return out.str();
}

TEST(OctreeBinary, WritesOctoMapsBytesAndReadsThemBackWithoutPrinting) {
  const octomap::OcTree tree = SampleTree();
  ::testing::internal::CaptureStderr();
  const std::string bytes = OctreeBinaryBytes(tree);
  const std::unique_ptr<octomap::OcTree> read = ReadOctreeBinary(bytes, "sample");
  const std::string printed = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(printed, "");
  EXPECT_EQ(bytes, OctoMapBytes(tree));
  ASSERT_NE(read, nullptr);
  EXPECT_EQ(read->size(), tree.size());
  EXPECT_DOUBLE_EQ(read->getResolution(), 0.00252);
  EXPECT_EQ(OctreeBinaryBytes(*read), bytes);
}

TEST(OctreeBinary, HeadersThatDoNotMatchTheDataAreRefusedByName) {
  const std::string bytes = OctreeBinaryBytes(SampleTree());
  const auto error = [](const std::string& candidate) {
    try {
      ReadOctreeBinary(candidate, "map 'm'");
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  std::string other_type = bytes;
  other_type.replace(other_type.find("id OcTree"), 9, "id ColorO");
  EXPECT_NE(error(other_type).find("map 'm': not an OctoMap binary (.bt) OcTree (type 'ColorO'"),
            std::string::npos);
  std::string endless = bytes;
  const size_t res_at = endless.find("res ") + 4;
  endless.replace(res_at, endless.find('\n', res_at) - res_at, "inf");
  EXPECT_NE(error(endless).find("not an OctoMap binary"), std::string::npos) << error(endless);
  std::string more_nodes = bytes;
  const size_t size_at = more_nodes.find("size ") + 5;
  more_nodes.insert(size_at, "1");
  EXPECT_NE(error(more_nodes).find("its header says 1"), std::string::npos) << error(more_nodes);
  EXPECT_NE(error("# Octomap OcTree binary file\nid OcTree\n").find("not an OctoMap binary"),
            std::string::npos);
  EXPECT_NE(error("# something else\nid OcTree\nsize 1\nres 0.1\ndata\n").find("not an OctoMap"),
            std::string::npos);
}

}  // namespace
}  // namespace avc::ppr
