// The patch MVS on a textured plane rendered analytically (z = 0 seen from five cameras):
// points on the plane, normals along +z, and the same bytes for one or two threads.

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/mvs/patch/patch_mvs.h"
#include "tests/core/mvs/patch/patch_test_scenes.h"

namespace avc::mvs {
namespace {

constexpr int kWidth = 320, kHeight = 240;
constexpr double kDistance = 0.5;

const std::vector<dataset::View>& PlaneViews() {
  static const auto views = testing::TexturedPlaneViews(5, kWidth, kHeight, kDistance, 0.3, 7);
  return views;
}

double Quantile(std::vector<double> values, double q) {
  std::sort(values.begin(), values.end());
  return values[std::min(values.size() - 1, static_cast<size_t>(q * values.size()))];
}

TEST(PatchMvsPlane, PointsLieOnThePlaneWithItsNormal) {
  const MvsPoints points = RunPatchMvs(PlaneViews(), {}, PatchMvsOptions{});
  ASSERT_EQ(points.Validate(), "");
  // Measured 8,667 points (the plane covers ~60 % of each image).
  EXPECT_GT(points.size(), 7000u);
  // One pixel at the plane is ~ distance / f = 0.5 / 288 = 1.7 mm.
  const double pixel = kDistance / (0.9 * kWidth);
  std::vector<double> offsets, angles;
  for (size_t i = 0; i < points.size(); ++i) {
    offsets.push_back(std::abs(points.cloud.positions[i].z()) / pixel);
    angles.push_back(std::acos(std::min(1.0, double(points.cloud.normals[i].z()))) * 180 / M_PI);
    EXPECT_GE(points.views[i].size(), 3u);
    EXPECT_TRUE(std::is_sorted(points.views[i].begin(), points.views[i].end()));
    EXPECT_GE(points.confidence[i], 0.7f);
  }
  // Measured: median 0.05 px, 90 % 0.15 px, 99 % 0.28 px; normals 2.0 / 4.1 deg (median, 90 %).
  EXPECT_LT(Quantile(offsets, 0.5), 0.1);
  EXPECT_LT(Quantile(offsets, 0.9), 0.2);
  EXPECT_LT(Quantile(offsets, 0.99), 0.4);
  EXPECT_LT(Quantile(angles, 0.5), 3.0);
  EXPECT_LT(Quantile(angles, 0.9), 6.0);
  // Colours are the texture's (20..235), not black.
  size_t dark = 0;
  for (const auto& c : points.cloud.colors) dark += (c.cast<int>().sum() < 30);
  EXPECT_LT(dark, points.size() / 100);
}

TEST(PatchMvsPlane, AUniformlyColouredRegionGivesNoPoints) {
  // The plane's half x > 2 cm painted one green: R, G and B differ, but nothing varies. A patch
  // there has no texture and must not match (its channels' different levels are not texture).
  std::vector<dataset::View> views = PlaneViews();
  for (dataset::View& view : views) {
    const Eigen::Matrix3d r = view.camera.T_cam_world.linear();
    const Eigen::Vector3d centre = view.camera.Centre();
    for (int v = 0; v < view.image.rows; ++v) {
      for (int u = 0; u < view.image.cols; ++u) {
        const Eigen::Vector3d ray =
            r.transpose() * view.camera.intrinsics.Ray({double(u), double(v)});
        const Eigen::Vector3d p = centre - centre.z() / ray.z() * ray;
        if (p.x() > 0.02) view.image.at<cv::Vec3b>(v, u) = cv::Vec3b(40, 120, 30);
      }
    }
  }
  const MvsPoints points = RunPatchMvs(views, {}, PatchMvsOptions{});
  ASSERT_GT(points.size(), 2000u);  // the textured half still works
  size_t inside_uniform = 0;
  // Half a window (2 px, ~3.5 mm) plus a cell from the edge, patches still see texture.
  for (const auto& p : points.cloud.positions) inside_uniform += p.x() > 0.03f;
  EXPECT_LT(inside_uniform, points.size() / 100) << inside_uniform << " of " << points.size();
}

TEST(PatchMvsPlane, SameBytesForOneAndTwoThreads) {
  auto run = [](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    PatchMvsOptions options;
    options.rounds = 2;
    return RunPatchMvs(PlaneViews(), {}, options);
  };
  const MvsPoints one = run(1), two = run(2);
  ASSERT_EQ(one.size(), two.size());
  ASSERT_GT(one.size(), 1000u);
  for (size_t i = 0; i < one.size(); ++i) {
    ASSERT_EQ(std::memcmp(one.cloud.positions[i].data(), two.cloud.positions[i].data(), 12), 0)
        << "point " << i;
    ASSERT_EQ(std::memcmp(one.cloud.normals[i].data(), two.cloud.normals[i].data(), 12), 0);
    ASSERT_EQ(one.cloud.colors[i], two.cloud.colors[i]);
    ASSERT_EQ(one.confidence[i], two.confidence[i]);
    ASSERT_EQ(one.views[i], two.views[i]);
  }
}

}  // namespace
}  // namespace avc::mvs
