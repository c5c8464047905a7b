// The plane sweep recovers textured planes (fronto-parallel and slanted 35 degrees) from
// synthetic views made by warping a random texture, with and without a proxy, and gives the
// same bits with one or two threads.

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

#include "core/mvs/plane_sweep/plane_sweep_mvs.h"
#include "tests/core/mvs/plane_sweep/sweep_test_scenes.h"

namespace avc::mvs {
namespace {

struct PlaneFit {
  double median_distance = 0;  // metres
  double inlier_fraction = 0;  // within 1 mm of the plane
  double median_normal_dot = 0;
};

PlaneFit MeasurePlane(const MvsPoints& points, const Eigen::Vector3d& normal) {
  std::vector<double> distances, dots;
  size_t inliers = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    const double d = std::abs(normal.dot(points.cloud.positions[i].cast<double>()));
    distances.push_back(d);
    dots.push_back(std::abs(normal.dot(points.cloud.normals[i].cast<double>())));
    inliers += d <= 0.001 ? 1 : 0;
  }
  PlaneFit fit;
  if (distances.empty()) return fit;
  std::nth_element(distances.begin(), distances.begin() + distances.size() / 2, distances.end());
  std::nth_element(dots.begin(), dots.begin() + dots.size() / 2, dots.end());
  fit.median_distance = distances[distances.size() / 2];
  fit.median_normal_dot = dots[dots.size() / 2];
  fit.inlier_fraction = static_cast<double>(inliers) / static_cast<double>(points.size());
  return fit;
}

void ExpectPlaneRecovered(double tilt, const MvsBounds& bounds_override, bool use_override,
                          size_t min_points) {
  const sweep_test::TexturedPlane scene = sweep_test::MakeTexturedPlane(tilt, 7);
  const MvsPoints points =
      RunPlaneSweep(scene.views, use_override ? bounds_override : scene.bounds, {});
  ASSERT_EQ(points.Validate(), "");
  const PlaneFit fit = MeasurePlane(points, scene.normal);
  std::cout << "tilt " << tilt << (use_override ? " (no proxy)" : "") << ": " << points.size()
            << " points, median distance " << fit.median_distance * 1e3 << " mm, within 1 mm "
            << fit.inlier_fraction << ", median |n.n_true| " << fit.median_normal_dot << "\n";
  EXPECT_GT(points.size(), min_points);
  EXPECT_LT(fit.median_distance, 0.0003);
  EXPECT_GT(fit.inlier_fraction, 0.95);
  EXPECT_GT(fit.median_normal_dot, 0.95);
  for (size_t i = 0; i < points.size(); ++i) {
    ASSERT_GE(points.views[i].size(), 3u) << "point " << i;
    ASSERT_GT(points.confidence[i], 0.59f) << "point " << i;
  }
}

TEST(PlaneSweepPlanes, RecoversFrontoParallelPlane) { ExpectPlaneRecovered(0.0, {}, false, 30000); }

TEST(PlaneSweepPlanes, RecoversSlantedPlane) {
  ExpectPlaneRecovered(35.0 * M_PI / 180.0, {}, false, 25000);
}

TEST(PlaneSweepPlanes, RecoversPlaneWithoutProxy) {
  ExpectPlaneRecovered(0.3, MvsBounds{}, true, 11000);
}

TEST(PlaneSweepPlanes, NormalsFaceTheCamerasAndColoursAreTheTexture) {
  const sweep_test::TexturedPlane scene = sweep_test::MakeTexturedPlane(0.2, 3);
  const MvsPoints points = RunPlaneSweep(scene.views, scene.bounds, {});
  ASSERT_GT(points.size(), 1000u);
  for (size_t i = 0; i < points.size(); ++i) {
    Eigen::Vector3f to_cameras = Eigen::Vector3f::Zero();
    for (uint32_t v : points.views[i]) {
      to_cameras +=
          (scene.views[v].camera.Centre().cast<float>() - points.cloud.positions[i]).normalized();
    }
    ASSERT_GT(points.cloud.normals[i].dot(to_cameras), 0) << "point " << i;
    ASSERT_NEAR(points.cloud.normals[i].norm(), 1.0f, 1e-4f);
    // A grey texture: red, green and blue agree.
    ASSERT_EQ(points.cloud.colors[i].x(), points.cloud.colors[i].y());
  }
}

TEST(PlaneSweepPlanes, SameBitsWithOneOrTwoThreads) {
  const sweep_test::TexturedPlane scene = sweep_test::MakeTexturedPlane(0.4, 11);
  auto run = [&](int threads) {
    tbb::global_control control(tbb::global_control::max_allowed_parallelism,
                                static_cast<size_t>(threads));
    return RunPlaneSweep(scene.views, scene.bounds, {});
  };
  const MvsPoints one = run(1);
  const MvsPoints two = run(2);
  ASSERT_GT(one.size(), 1000u);
  ASSERT_EQ(one.size(), two.size());
  EXPECT_EQ(one.cloud.positions, two.cloud.positions);
  EXPECT_EQ(one.cloud.normals, two.cloud.normals);
  EXPECT_EQ(one.cloud.colors, two.cloud.colors);
  EXPECT_EQ(one.confidence, two.confidence);
  EXPECT_EQ(one.views, two.views);
}

}  // namespace
}  // namespace avc::mvs
