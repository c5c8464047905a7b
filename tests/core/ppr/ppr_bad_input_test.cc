// Bad cameras, masks, boxes and octrees give std::invalid_argument naming the view and the field.

#include <gtest/gtest.h>
#include <octomap/OcTree.h>

#include <functional>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include "core/ppr/octree_voxels.h"
#include "core/ppr/plant_proxy.h"
#include "core/ppr/proxy_bounds.h"
#include "tests/core/ppr/synthetic_views.h"

namespace avc::ppr {
namespace {

// Runs `call` and returns the std::invalid_argument message ("" if none was thrown).
template <class Call>
std::string InvalidArgumentMessage(Call&& call) {
  try {
    call();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

class PlantProxyBadInput : public ::testing::Test {
 protected:
  camera::Camera camera_ = testing::LookAt({0.4, 0, 0.1}, Eigen::Vector3d::Zero());
  cv::Mat mask_ = cv::Mat(480, 640, CV_8UC1, cv::Scalar(255));
  PlantProxy proxy_{
      Eigen::AlignedBox3d(Eigen::Vector3d::Constant(-0.05), Eigen::Vector3d::Constant(0.05))};
};

TEST_F(PlantProxyBadInput, MaskSizeMismatchNamesTheView) {
  const cv::Mat small(240, 320, CV_8UC1, cv::Scalar(0));
  const std::string message =
      InvalidArgumentMessage([&] { proxy_.AddView(camera_, small, "view_07.png"); });
  EXPECT_NE(message.find("view_07.png"), std::string::npos) << message;
  EXPECT_NE(message.find("320x240"), std::string::npos) << message;
  EXPECT_EQ(proxy_.view_count(), 0);
}

TEST_F(PlantProxyBadInput, EmptyMaskNamesTheView) {
  dataset::View view{"view_02.png", camera_, {}, {}};
  const std::string message = InvalidArgumentMessage([&] { proxy_.AddView(view); });
  EXPECT_NE(message.find("view_02.png"), std::string::npos) << message;
  EXPECT_NE(message.find("mask is empty"), std::string::npos) << message;
}

TEST_F(PlantProxyBadInput, WrongMaskTypeIsRefused) {
  const cv::Mat colour(480, 640, CV_8UC3, cv::Scalar(0, 0, 0));
  const std::string message = InvalidArgumentMessage([&] { proxy_.AddView(camera_, colour); });
  EXPECT_NE(message.find("#0"), std::string::npos) << message;
  EXPECT_NE(message.find("CV_8UC1"), std::string::npos) << message;
}

TEST_F(PlantProxyBadInput, NanPoseNamesTheViewAndThePose) {
  camera::Camera bad = camera_;
  bad.T_cam_world.translation().y() = std::numeric_limits<double>::quiet_NaN();
  const std::string message =
      InvalidArgumentMessage([&] { proxy_.AddView(bad, mask_, "view_11.png"); });
  EXPECT_NE(message.find("view_11.png"), std::string::npos) << message;
  EXPECT_NE(message.find("T_cam_world"), std::string::npos) << message;
  // Nothing was carved by the refused view.
  EXPECT_EQ(proxy_.Counts().free, 0u);
}

TEST_F(PlantProxyBadInput, BadIntrinsicsAreRefused) {
  camera::Camera bad = camera_;
  bad.intrinsics.fx = -1;
  const std::string message = InvalidArgumentMessage([&] { proxy_.AddView(bad, mask_, "v"); });
  EXPECT_NE(message.find("intrinsics"), std::string::npos) << message;
}

TEST(PlantProxyBadBox, EmptyOrNonFiniteBoxIsRefused) {
  EXPECT_THROW(PlantProxy{Eigen::AlignedBox3d()}, std::invalid_argument);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(PlantProxy(Eigen::AlignedBox3d(Eigen::Vector3d(nan, 0, 0), Eigen::Vector3d::Ones())),
               std::invalid_argument);
  ProxyOptions options;
  options.final_voxel_size = 1e-7;  // 1 m box in 0.1 um voxels: beyond OctoMap's key range
  EXPECT_THROW(
      PlantProxy(Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones()), options),
      std::invalid_argument);
}

TEST(PlantProxyBounds, NoViewsIsAClearError) {
  const std::string message = InvalidArgumentMessage(
      [] { BoundsFromViews(std::vector<camera::Camera>{}, std::vector<cv::Mat>{}); });
  EXPECT_NE(message.find("no views"), std::string::npos) << message;
}

TEST(PlantProxyBounds, MismatchedCountsAndParallelAxesAreRefused) {
  const auto a = testing::LookAt({0.4, 0, 0}, Eigen::Vector3d::Zero());
  const auto b = testing::LookAt({0.5, 0, 0}, Eigen::Vector3d::Zero());
  EXPECT_THROW(BoundsFromViews({a, b}, {cv::Mat(480, 640, CV_8UC1)}), std::invalid_argument);
  const std::string message = InvalidArgumentMessage([&] { BoxFromCameras({a, b}); });
  EXPECT_NE(message.find("parallel"), std::string::npos) << message;
}

TEST(PlantProxyBounds, EmptyMasksLeaveNothingToBound) {
  const auto cameras = testing::RingCameras(6, 0.4);
  const std::vector<cv::Mat> masks(6, cv::Mat(480, 640, CV_8UC1, cv::Scalar(0)));
  EXPECT_THROW(BoundsFromViews(cameras, masks), std::runtime_error);
}

TEST(OccupiedVoxelsFromBinary, GarbageWrongSizeAndHugeTreesAreRefused) {
  const auto message = [](const std::function<void()>& read) {
    try {
      read();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message([] { OccupiedVoxelsFromBinary("", 0.002, "map 'x'"); }).find("map 'x'"),
            std::string::npos);
  EXPECT_NE(message([] {
              OccupiedVoxelsFromBinary("# Octomap OcTree binary file\nid OcTree\n", 0.002,
                                       "map 'x'");
            }).find("not an OctoMap binary"),
            std::string::npos);

  octomap::OcTree tree(0.002);
  tree.updateNode(octomap::point3d(0.01f, 0.01f, 0.01f), true);
  std::ostringstream bytes;
  ASSERT_TRUE(tree.writeBinaryConst(bytes));
  // Node data cut short, or inner children all the way down (OctoMap's own reader would read
  // past the end and build nodes for minutes): refused from the bytes, at once.
  const std::string header = bytes.str().substr(0, bytes.str().find("\ndata\n") + 6);
  EXPECT_NE(message([&] {
              OccupiedVoxelsFromBinary(bytes.str().substr(0, bytes.str().size() - 1), 0.002, "cut");
            }).find("ends inside the tree"),
            std::string::npos);
  EXPECT_NE(message([&] {
              OccupiedVoxelsFromBinary(header + std::string(40, '\xff'), 0.002, "inner");
            }).find("deepest level"),
            std::string::npos);
  EXPECT_EQ(OccupiedVoxelsFromBinary(bytes.str(), 0.002, "one").occupied_centres.size(), 1u);
  EXPECT_NE(message([&] {
              OccupiedVoxelsFromBinary(bytes.str(), 0.003, "one");
            }).find("is not the voxel size"),
            std::string::npos);
  // Eight occupied children prune into one node of 8 voxels: over a limit of 7.
  for (float x : {0.0005f, 0.0025f}) {
    for (float y : {0.0005f, 0.0025f}) {
      for (float z : {0.0005f, 0.0025f}) tree.updateNode(octomap::point3d(x, y, z), true);
    }
  }
  tree.prune();
  std::ostringstream pruned;
  ASSERT_TRUE(tree.writeBinaryConst(pruned));
  EXPECT_NE(message([&] {
              OccupiedVoxelsFromBinary(pruned.str(), 0.002, "big", {.max_voxels = 7});
            }).find("refusing to expand"),
            std::string::npos);
  EXPECT_EQ(OccupiedVoxelsFromBinary(pruned.str(), 0.002, "big").occupied_centres.size(), 9u);
}

}  // namespace
}  // namespace avc::ppr
