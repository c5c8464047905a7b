// A proxy's voxels drawn into a view: each covers its projected footprint, nothing behind the
// camera is drawn.

#include "core/ppr/proxy_silhouette.h"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

namespace avc::ppr {
namespace {

camera::Camera LookingAlongZ() {
  camera::Camera camera;
  camera.intrinsics = {200, 100, 100, 100, 99.5, 49.5, {}};
  return camera;  // at the origin, looking along +z
}

TEST(ProxySilhouette, CoversEachVoxelsFootprint) {
  // A 10 mm voxel 1 m ahead projects to a 1 px square; its bounding sphere to about 1.7 px.
  const mvs::MvsBounds proxy{{Eigen::Vector3f(0, 0, 1), Eigen::Vector3f(0.2f, 0, 1)}, 0.01};
  const cv::Mat silhouette = ProxySilhouette(proxy, LookingAlongZ());
  ASSERT_EQ(silhouette.size(), cv::Size(200, 100));
  EXPECT_EQ(silhouette.at<uint8_t>(50, 100), 255);
  EXPECT_EQ(silhouette.at<uint8_t>(49, 99), 255);
  EXPECT_EQ(silhouette.at<uint8_t>(50, 120), 255);  // the second voxel, 20 px to the right
  EXPECT_EQ(silhouette.at<uint8_t>(50, 110), 0);
  EXPECT_LE(cv::countNonZero(silhouette), 2 * 16);
}

TEST(ProxySilhouette, DrawsNothingBehindTheCamera) {
  const mvs::MvsBounds proxy{{Eigen::Vector3f(0, 0, -1), Eigen::Vector3f(0, 0, 0.001f)}, 0.01};
  EXPECT_EQ(cv::countNonZero(ProxySilhouette(proxy, LookingAlongZ())), 0);
}

}  // namespace
}  // namespace avc::ppr
