// Coverage by views on cases with known answers: a plane seen from three cameras, from two,
// with one camera's view partly blocked, and at grazing angles either side of the limit.

#include "core/eval/coverage.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tests/core/eval/test_scenes.h"

namespace avc::eval {
namespace {

using geometry::labels::kLeafBase;
using geometry::labels::kPot;
using test::LookAt;
using test::Rectangle;

// Three cameras 0.5 m above a 0.2 m square, 0.2 m apart, all looking at its centre.
std::vector<camera::Camera> CamerasAbove() {
  return {LookAt({-0.2, 0, 0.5}, {0, 0, 0}), LookAt({0, 0, 0.5}, {0, 0, 0}),
          LookAt({0.2, 0, 0.5}, {0, 0, 0})};
}

TEST(Coverage, ThreeCamerasCoverAPlane) {
  const CoverageModel model(Rectangle(-0.1, 0.1, -0.1, 0.1, 0, 4), 1e5, 1);
  const CoverageResult result = model.Evaluate(CamerasAbove());
  EXPECT_EQ(result.cameras, 3u);
  EXPECT_NEAR(static_cast<double>(result.samples), 4000.0, 10.0);
  EXPECT_EQ(result.covered, result.samples);
  EXPECT_EQ(result.fraction, 1.0);
  ASSERT_EQ(result.view_counts.size(), model.samples().size());
  for (int count : result.view_counts) EXPECT_EQ(count, 3);
  ASSERT_EQ(result.organs.size(), 1u);
  EXPECT_EQ(result.organs[0].name, "leaf 0");
  EXPECT_EQ(result.organs[0].fraction, 1.0);
  EXPECT_EQ(result.view_count_histogram, (std::vector<size_t>{0, 0, 0, result.samples}));
}

TEST(Coverage, LeavesAreSeenFromBothSides) {
  const CoverageModel model(Rectangle(-0.1, 0.1, -0.1, 0.1, 0, 4), 1e5, 1);
  const std::vector<camera::Camera> below = {LookAt({-0.2, 0, -0.5}, {0, 0, 0}),
                                             LookAt({0, 0, -0.5}, {0, 0, 0}),
                                             LookAt({0.2, 0, -0.5}, {0, 0, 0})};
  EXPECT_EQ(model.Evaluate(below).fraction, 1.0);
}

TEST(Coverage, TwoCamerasAreNotEnoughForThreeViews) {
  const CoverageModel model(Rectangle(-0.1, 0.1, -0.1, 0.1, 0, 4), 1e5, 1);
  std::vector<camera::Camera> cameras = CamerasAbove();
  cameras.pop_back();
  const CoverageResult result = model.Evaluate(cameras);
  EXPECT_EQ(result.covered, 0u);
  EXPECT_EQ(result.fraction, 0.0);
  for (int count : result.view_counts) EXPECT_EQ(count, 2);
  CoverageOptions two_views;
  two_views.min_views = 2;
  const CoverageModel lenient(Rectangle(-0.1, 0.1, -0.1, 0.1, 0, 4), 1e5, 1, two_views);
  EXPECT_EQ(lenient.Evaluate(cameras).fraction, 1.0);
}

TEST(Coverage, ABlockerHidesItsShadowFromOneCamera) {
  // A 2 cm square 0.1 m below the middle camera shadows the central 10 cm square of the plane
  // (scale 0.5 / 0.1 = 5) from it only; the side cameras' rays pass it 14-18 cm away.
  geometry::Mesh scene = Rectangle(-0.1, 0.1, -0.1, 0.1, 0, 4, kLeafBase);
  scene.Append(Rectangle(-0.01, 0.01, -0.01, 0.01, 0.4, 1, kPot));
  const CoverageModel model(scene, 2e5, 1);
  const CoverageResult result = model.Evaluate(CamerasAbove());
  ASSERT_EQ(result.organs.size(), 2u);
  const OrganCoverage& plane = result.organs[1];
  EXPECT_EQ(plane.label, kLeafBase);
  EXPECT_NEAR(plane.fraction, 0.75, 0.02);
  // Sample by sample: two views inside the shadow, three outside.
  const SurfaceSamples& samples = model.samples();
  size_t checked = 0;
  for (size_t i = 0; i < samples.size(); ++i) {
    const Eigen::Vector3d& p = samples.points[i];
    if (p.z() != 0) continue;
    const double edge = std::max(std::abs(p.x()), std::abs(p.y()));
    if (std::abs(edge - 0.05) < 1e-6) continue;  // on the shadow's border
    EXPECT_EQ(result.view_counts[i], edge < 0.05 ? 2 : 3) << p.transpose();
    ++checked;
  }
  EXPECT_GT(checked, 7000u);
}

TEST(Coverage, GrazingViewsBeyondTheLimitDoNotCount) {
  const geometry::Mesh patch = Rectangle(-0.005, 0.005, -0.005, 0.005, 0, 1);
  // Three cameras 1 m away around the patch, the view direction at `angle` from its normal.
  auto cameras_at = [](double angle_deg) {
    std::vector<camera::Camera> cameras;
    const double angle = angle_deg * std::numbers::pi / 180;
    for (int k = 0; k < 3; ++k) {
      const double azimuth = 2 * std::numbers::pi * k / 3;
      const Eigen::Vector3d centre(std::sin(angle) * std::cos(azimuth),
                                   std::sin(angle) * std::sin(azimuth), std::cos(angle));
      cameras.push_back(LookAt(centre, {0, 0, 0}, Eigen::Vector3d::UnitZ()));
    }
    return cameras;
  };
  const CoverageModel model(patch, 1e7, 1);
  EXPECT_EQ(model.Evaluate(cameras_at(80)).fraction, 0.0);
  EXPECT_EQ(model.Evaluate(cameras_at(70)).fraction, 1.0);
  CoverageOptions steep;
  steep.max_grazing_deg = 85;
  const CoverageModel lenient(patch, 1e7, 1, steep);
  EXPECT_EQ(lenient.Evaluate(cameras_at(80)).fraction, 1.0);
}

TEST(Coverage, PointsOutsideTheImageAreNotSeen) {
  const CoverageModel model(Rectangle(-0.1, 0.1, -0.1, 0.1, 0, 4), 1e5, 1);
  // Looking at the corner region from close by: only part of the plane is in the image.
  const camera::Camera close = LookAt({0.1, 0.1, 0.1}, {0.1, 0.1, 0});
  const std::vector<uint8_t> seen = model.SeenBy(close);
  // Half-widths 0.1 * 320 / 500 = 0.064 m and 0.1 * 240 / 500 = 0.048 m around the corner.
  for (size_t i = 0; i < seen.size(); ++i) {
    const Eigen::Vector3d& p = model.samples().points[i];
    const bool inside = p.x() > 0.1 - 0.064 + 1e-4 && p.y() > 0.1 - 0.048 + 1e-4;
    const bool outside = p.x() < 0.1 - 0.064 - 1e-4 || p.y() < 0.1 - 0.048 - 1e-4;
    if (inside) {
      EXPECT_EQ(seen[i], 1) << p.transpose();
    }
    if (outside) {
      EXPECT_EQ(seen[i], 0) << p.transpose();
    }
  }
}

TEST(Coverage, DistortionFoldOverDoesNotCountAsSeen) {
  // Strong barrel distortion (k1 = -0.3): the distorted radius r (1 - 0.3 r^2) peaks at
  // r = 1.05 and falls again, so points far outside the field of view project back into the
  // image. A camera 0.1 m above a 1 m plane: r is the horizontal distance / 0.1 m.
  const CoverageModel model(Rectangle(-0.5, 0.5, -0.5, 0.5, 0, 8), 2e4, 1);
  camera::Camera camera = LookAt({0, 0, 0.1}, {0, 0, 0});
  camera.intrinsics.distortion = {-0.3, 0, 0, 0, 0};
  const std::vector<uint8_t> seen = model.SeenBy(camera);
  size_t folded_into_image = 0, near_axis = 0;
  for (size_t i = 0; i < seen.size(); ++i) {
    const Eigen::Vector3d& p = model.samples().points[i];
    const double r = p.head<2>().norm() / 0.1;
    if (r < 0.5) {
      EXPECT_EQ(seen[i], 1) << p.transpose();
      ++near_axis;
    }
    if (r > 1.155) {
      EXPECT_EQ(seen[i], 0) << p.transpose();
      const std::optional<Eigen::Vector2d> pixel = camera.Project(p);
      folded_into_image +=
          pixel && pixel->x() > 0 && pixel->x() < 639 && pixel->y() > 0 && pixel->y() < 479;
    }
  }
  EXPECT_GT(near_axis, 10u);
  EXPECT_GT(folded_into_image, 100u);  // the case the check exists for does occur
}

TEST(Coverage, BadCamerasAndOptionsGiveClearErrors) {
  const geometry::Mesh plane = Rectangle(-0.1, 0.1, -0.1, 0.1, 0, 1);
  const CoverageModel model(plane, 1e4, 1);
  std::vector<camera::Camera> cameras = CamerasAbove();
  cameras[1].intrinsics.fx = 0;
  try {
    model.Evaluate(cameras);
    ADD_FAILURE() << "a camera with fx = 0 was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("camera 1: focal lengths"), std::string::npos) << e.what();
  }
  CoverageOptions bad;
  bad.min_views = 0;
  EXPECT_THROW(CoverageModel(plane, 1e4, 1, bad), std::invalid_argument);
  bad = CoverageOptions();
  bad.max_grazing_deg = 120;
  EXPECT_THROW(CoverageModel(plane, 1e4, 1, bad), std::invalid_argument);
}

}  // namespace
}  // namespace avc::eval
