// The pieces both MVS methods share: the points' PLY form, the plant proxy's depth range and
// occupancy lookup, and the choice of neighbouring views.

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include "core/mvs/depth_range.h"
#include "core/mvs/mvs_points_io.h"
#include "core/mvs/occupancy_lookup.h"
#include "core/mvs/view_neighbours.h"
#include "tests/support/test_support.h"

namespace avc::mvs {
namespace {

MvsPoints SomePoints() {
  MvsPoints points;
  for (int i = 0; i < 5; ++i) {
    points.cloud.positions.emplace_back(0.1f * i, -0.02f, 0.3f + 0.001f * i);
    points.cloud.normals.push_back(Eigen::Vector3f(1, i, 2).normalized());
    points.cloud.colors.emplace_back(10 * i, 200, 255 - i);
    points.confidence.push_back(0.5f + 0.1f * i);
    std::vector<uint32_t> views;
    for (uint32_t v = 0; v < static_cast<uint32_t>(i); ++v) views.push_back(3 * v + 1);
    points.views.push_back(views);
  }
  return points;
}

void ExpectSame(const MvsPoints& a, const MvsPoints& b) {
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(a.cloud.positions, b.cloud.positions);
  EXPECT_EQ(a.cloud.normals, b.cloud.normals);
  EXPECT_EQ(a.cloud.colors, b.cloud.colors);
  EXPECT_EQ(a.confidence, b.confidence);
  EXPECT_EQ(a.views, b.views);
}

TEST(MvsPointsPly, RoundTripsBinaryAndAscii) {
  testing::TempDir dir;
  const MvsPoints points = SomePoints();
  for (bool binary : {true, false}) {
    const auto path = dir / (binary ? "b.ply" : "a.ply");
    WriteMvsPointsPly(path, points, binary);
    ExpectSame(ReadMvsPointsPly(path), points);
  }
  EXPECT_EQ(MvsPointsToPly(points), MvsPointsToPly(points));
}

TEST(MvsPointsPly, RefusesInconsistentPointsAndNamesBadFiles) {
  MvsPoints points = SomePoints();
  points.views[2] = {4, 1};
  EXPECT_THROW(MvsPointsToPly(points), std::invalid_argument);
  points = SomePoints();
  points.confidence[1] = 1.5f;
  EXPECT_NE(points.Validate().find("point 1: confidence"), std::string::npos);
  points.confidence.pop_back();
  EXPECT_NE(points.Validate().find("4 confidences for 5 points"), std::string::npos);

  testing::TempDir dir;
  testing::WriteFile(dir / "bad.ply",
                     "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n1\n");
  try {
    ReadMvsPointsPly(dir / "bad.ply");
    FAIL() << "read a file without y and z";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("bad.ply"), std::string::npos) << e.what();
  }
}

camera::Camera LookingDownZ(double x_offset) {
  camera::Camera camera;
  auto& k = camera.intrinsics;
  k.width = 100;
  k.height = 80;
  k.fx = k.fy = 100;
  k.cx = 49.5;
  k.cy = 39.5;
  camera.T_cam_world.translation() = Eigen::Vector3d(-x_offset, 0, 1);  // camera at z = -1
  return camera;
}

TEST(DepthRange, CoversTheVoxelsAndBracketsTheirDepth) {
  MvsBounds bounds;
  bounds.voxel_size = 0.01;
  // Far enough apart across the image that no two voxels' squares overlap.
  for (int i = -2; i <= 2; ++i) bounds.occupied_centres.emplace_back(0.05f * i, 0, 0.05f * i);
  const DepthRange range = ComputeDepthRange(LookingDownZ(0), bounds, 0.002);
  EXPECT_FALSE(range.Covers(0, 0));
  EXPECT_FALSE(range.Covers(49, 70));
  ASSERT_TRUE(range.Covers(49, 39));  // voxel 0 at depth 1
  EXPECT_NEAR(range.near_depth.at<float>(39, 50), 1 - 0.005 * std::sqrt(3.0) - 0.002, 1e-5);
  // Voxel +2 at x = 0.1, depth 1.1 images at u = 49.5 + 100 * 0.1 / 1.1.
  const int u = static_cast<int>(std::lround(49.5 + 100 * 0.1 / 1.1));
  ASSERT_TRUE(range.Covers(u, 39));
  EXPECT_NEAR(range.far_depth.at<float>(39, u), 1.1 + 0.005 * std::sqrt(3.0) + 0.002, 1e-5);
  EXPECT_EQ(cv::countNonZero(ComputeDepthRange(LookingDownZ(0), MvsBounds{}, 0).far_depth), 0);
}

// Its coverage is the proxy's silhouette, which the builder cuts masks to: each voxel covers its
// projected footprint and nothing behind the camera is drawn.
TEST(DepthRange, CoversEachVoxelsFootprintOnlyInFrontOfTheCamera) {
  camera::Camera camera;
  camera.intrinsics = {200, 100, 100, 100, 99.5, 49.5, {}};  // at the origin, looking along +z
  // A 10 mm voxel 1 m ahead projects to a 1 px square; its bounding sphere to about 1.7 px.
  const MvsBounds proxy{{Eigen::Vector3f(0, 0, 1), Eigen::Vector3f(0.2f, 0, 1)}, 0.01};
  const DepthRange range = ComputeDepthRange(camera, proxy, 0);
  EXPECT_TRUE(range.Covers(100, 50));
  EXPECT_TRUE(range.Covers(99, 49));
  EXPECT_TRUE(range.Covers(120, 50));  // the second voxel, 20 px to the right
  EXPECT_FALSE(range.Covers(110, 50));
  EXPECT_LE(cv::countNonZero(range.far_depth), 2 * 16);
  const MvsBounds behind{{Eigen::Vector3f(0, 0, -1), Eigen::Vector3f(0, 0, 0.001f)}, 0.01};
  EXPECT_EQ(cv::countNonZero(ComputeDepthRange(camera, behind, 0).far_depth), 0);
}

TEST(OccupancyLookup, FindsVoxelsAndTheirDilation) {
  MvsBounds bounds;
  bounds.voxel_size = 0.002;
  bounds.occupied_centres = {{0.101f, 0.201f, 0.301f}, {0.103f, 0.201f, 0.301f}};
  const OccupancyLookup lookup(bounds);
  EXPECT_TRUE(lookup.Contains({0.1015, 0.2005, 0.3019}));
  EXPECT_TRUE(lookup.Contains({0.1039, 0.2019, 0.3001}));
  EXPECT_FALSE(lookup.Contains({0.1051, 0.201, 0.301}));
  EXPECT_TRUE(lookup.Contains({0.1051, 0.201, 0.301}, 1));
  EXPECT_FALSE(lookup.Contains({0.1071, 0.201, 0.301}, 1));
  EXPECT_FALSE(lookup.Contains({std::nan(""), 0.201, 0.301}, 3));
  EXPECT_TRUE(OccupancyLookup(MvsBounds{}).Contains({5, 5, 5}));  // no proxy rules nothing out
}

camera::Camera OnRing(double angle) {
  const Eigen::Vector3d centre(std::cos(angle), std::sin(angle), 0.3);
  const Eigen::Vector3d z = (Eigen::Vector3d(0, 0, 0.05) - centre).normalized();
  const Eigen::Vector3d x = z.cross(Eigen::Vector3d::UnitZ()).normalized();
  Eigen::Matrix3d r;
  r << x.transpose(), z.cross(x).transpose(), z.transpose();
  camera::Camera camera = LookingDownZ(0);
  camera.T_cam_world.linear() = r;
  camera.T_cam_world.translation() = -r * centre;
  return camera;
}

TEST(ViewNeighbours, RanksRingNeighboursByAngle) {
  std::vector<camera::Camera> ring;
  for (int i = 0; i < 12; ++i) ring.push_back(OnRing(2 * M_PI * i / 12));
  const Eigen::Vector3d centre = NearestPointToAxes(ring);
  EXPECT_LT((centre - Eigen::Vector3d(0, 0, 0.05)).norm(), 1e-9);
  const auto neighbours = SelectNeighbours(ring, centre, {.max_neighbours = 4});
  ASSERT_EQ(neighbours.size(), 12u);
  // 30 deg apart on the ring is ~28 deg between rays: the nearest two are best, then 60 deg
  // (~55 deg between rays, inside the 60 deg limit); opposite views never qualify.
  EXPECT_EQ(neighbours[0], (std::vector<uint32_t>{1, 11, 2, 10}));
  EXPECT_EQ(neighbours[5], (std::vector<uint32_t>{4, 6, 3, 7}));
  camera::Camera away = OnRing(0);
  away.T_cam_world =
      Eigen::Isometry3d(Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitY())) * away.T_cam_world;
  ring.push_back(away);
  EXPECT_TRUE(SelectNeighbours(ring, centre)[12].empty());
}

}  // namespace
}  // namespace avc::mvs
