// Label images: the nearest face wins whatever the face order, background is 0, and a mesh of
// shared edges renders without cracks, also where distortion makes the renderer split faces.

#include <gtest/gtest.h>

#include "core/geometry/mesh.h"
#include "sim/render/renderer.h"
#include "tests/sim/render_test_scenes.h"

namespace avc::sim {
namespace {

using render_test::AddQuad;
using render_test::LookAt;

constexpr int32_t kNear = 107, kFar = 9;

// Two fronto-parallel squares seen from z above: the near one covers the middle of the far one.
Scene Overlap(bool near_first) {
  Scene scene;
  scene.name = "overlap";
  scene.materials = {render_test::TexturedMaterial(3)};
  geometry::Mesh near_square, far_square;
  AddQuad(&near_square, {-0.05f, -0.05f, 0.1f}, {0.1f, 0, 0}, {0, 0.1f, 0}, 3, kNear, 0);
  AddQuad(&far_square, {-0.15f, -0.15f, 0.0f}, {0.3f, 0, 0}, {0, 0.3f, 0}, 5, kFar, 0);
  scene.mesh = near_first ? near_square : far_square;
  scene.mesh.Append(near_first ? far_square : near_square);
  return scene;
}

camera::Camera TopCamera(bool distorted) {
  camera::Camera camera;
  camera.intrinsics = render_test::TestIntrinsics(distorted);
  camera.T_cam_world = LookAt({0.0, 0.0, 0.5}, {0, 0, 0}, Eigen::Vector3d::UnitY());
  return camera;
}

int32_t LabelAt(const RenderResult& result, const camera::Camera& camera,
                const Eigen::Vector3d& world) {
  const Eigen::Vector2d pixel = *camera.Project(world);
  return result.labels.at<int32_t>(static_cast<int>(std::lround(pixel.y())),
                                   static_cast<int>(std::lround(pixel.x())));
}

TEST(RenderLabels, NearFaceWinsWhateverTheFaceOrder) {
  const camera::Camera camera = TopCamera(true);
  for (bool near_first : {true, false}) {
    const RenderResult result = Render(Overlap(near_first), camera, RenderOptions{});
    EXPECT_EQ(LabelAt(result, camera, {0, 0, 0.1}), kNear) << "near_first " << near_first;
    EXPECT_EQ(LabelAt(result, camera, {0.03, -0.04, 0.1}), kNear);
    EXPECT_EQ(LabelAt(result, camera, {0.1, 0.1, 0}), kFar);
    EXPECT_EQ(LabelAt(result, camera, {-0.12, 0.07, 0}), kFar);
    EXPECT_EQ(result.labels.at<int32_t>(0, 0), geometry::labels::kBackground);
    EXPECT_EQ(result.depth.at<float>(0, 0), 0.0f);
    // Depth follows the label: 0.4 m to the near square, 0.5 m to the far one.
    const Eigen::Vector2d centre = *camera.Project({0, 0, 0.1});
    EXPECT_NEAR(result.depth.at<float>(static_cast<int>(std::lround(centre.y())),
                                       static_cast<int>(std::lround(centre.x()))),
                0.4, 1e-4);
  }
  // Both orders give the same label image.
  const RenderResult a = Render(Overlap(true), camera, RenderOptions{});
  const RenderResult b = Render(Overlap(false), camera, RenderOptions{});
  EXPECT_EQ(cv::countNonZero(a.labels != b.labels), 0);
}

TEST(RenderLabels, LabelCountsMatchTheProjectedAreas) {
  // Without distortion the squares image as exact squares: count their pixels.
  const camera::Camera camera = TopCamera(false);
  const RenderResult result = Render(Overlap(true), camera, RenderOptions{});
  const double near_side = 0.1 * camera.intrinsics.fx / 0.4;
  const double far_side = 0.3 * camera.intrinsics.fx / 0.5;
  const int near_pixels = cv::countNonZero(result.labels == kNear);
  const int far_pixels = cv::countNonZero(result.labels == kFar);
  const int background = cv::countNonZero(result.labels == 0);
  EXPECT_NEAR(near_pixels, near_side * near_side, 2 * near_side);
  EXPECT_NEAR(far_pixels, far_side * far_side - near_side * near_side, 2 * (far_side + near_side));
  EXPECT_EQ(near_pixels + far_pixels + background,
            camera.intrinsics.width * camera.intrinsics.height);
}

// Counts pixels whose ray meets the plane z = 0 inside the rectangle [x0, x1] x [y0, y1] (by more
// than a millimetre, ~1.5 px here) without having been given the label.
int Holes(double x0, double x1, double y0, double y1, int32_t label, const camera::Camera& camera,
          const RenderResult& result) {
  int holes = 0;
  const Eigen::Vector3d centre = camera.Centre();
  const Eigen::Matrix3d R_world_cam = camera.T_cam_world.linear().transpose();
  constexpr double kMargin = 1e-3;
  for (int v = 0; v < camera.intrinsics.height; ++v) {
    for (int u = 0; u < camera.intrinsics.width; ++u) {
      if (result.labels.at<int32_t>(v, u) == label) continue;
      const Eigen::Vector3d ray = R_world_cam * camera.intrinsics.Ray(Eigen::Vector2d(u, v));
      const Eigen::Vector3d p = centre - centre.z() / ray.z() * ray;
      holes += p.x() > x0 + kMargin && p.x() < x1 - kMargin && p.y() > y0 + kMargin &&
               p.y() < y1 - kMargin;
    }
  }
  return holes;
}

TEST(RenderLabels, SharedEdgesLeaveNoCracks) {
  // A coarse grid whose big cells distortion bends, so they are split, each edge as often as its
  // own bend needs: neighbours sharing an edge must split it alike or cracks open.
  geometry::Mesh mesh;
  AddQuad(&mesh, {-0.4f, -0.3f, 0}, {0.8f, 0, 0}, {0, 0.6f, 0}, 5, 5, 0);
  Scene scene;
  scene.name = "grid";
  scene.mesh = mesh;
  scene.materials = {render_test::TexturedMaterial(4)};
  camera::Camera camera = TopCamera(true);
  camera.T_cam_world = LookAt({0.05, -0.3, 0.3}, {0.0, 0.02, 0}, Eigen::Vector3d::UnitY());
  for (int samples : {1, 2}) {
    RenderOptions options;
    options.samples_per_pixel_axis = samples;
    const RenderResult result = Render(scene, camera, options);
    EXPECT_GT(result.stats.subdivided_faces, 0u);
    EXPECT_GT(cv::countNonZero(result.labels == 5), 150000);
    EXPECT_EQ(Holes(-0.4, 0.4, -0.3, 0.3, 5, camera, result), 0) << samples << " samples per axis";
  }
}

TEST(RenderLabels, IntersectingSurfacesSwitchAtTheirIntersection) {
  // Two large planes crossing along the line x = 0 on z = 0: left of it plane A is nearer, right
  // of it plane B; pixel centres more than 0.1 px from the imaged line must be labelled so.
  Scene scene;
  scene.name = "crossing planes";
  scene.materials = {render_test::TexturedMaterial(5)};
  AddQuad(&scene.mesh, {-0.3f, -0.3f, -0.06f}, {0.6f, 0, 0.12f}, {0, 0.6f, 0}, 4, 1, 0);
  AddQuad(&scene.mesh, {-0.3f, -0.3f, 0.09f}, {0.6f, 0, -0.18f}, {0, 0.6f, 0}, 4, 2, 0);
  const camera::Camera camera = TopCamera(true);
  const RenderResult result = Render(scene, camera, RenderOptions{});
  const Eigen::Vector3d centre = camera.Centre();
  const Eigen::Matrix3d R_world_cam = camera.T_cam_world.linear().transpose();
  int checked = 0, wrong = 0;
  for (int v = 0; v < camera.intrinsics.height; v += 2) {
    for (int u = 0; u < camera.intrinsics.width; ++u) {
      const Eigen::Vector3d ray = R_world_cam * camera.intrinsics.Ray(Eigen::Vector2d(u, v));
      const auto hit = render_test::CastRay(scene.mesh, centre, ray);
      if (!hit) continue;
      // Distance to the intersection line, in pixels: project the line's point at this row.
      const Eigen::Vector3d p = centre + hit->distance * ray;
      const Eigen::Vector2d on_line = *camera.Project({0.0, p.y(), 0.0});
      if (std::abs(on_line.x() - u) < 0.1) continue;
      ++checked;
      wrong += result.labels.at<int32_t>(v, u) != scene.mesh.face_labels[hit->face];
    }
  }
  EXPECT_GT(checked, 100000);
  EXPECT_EQ(wrong, 0);
}

}  // namespace
}  // namespace avc::sim
