// Depth and labels agree with rays cast through the pixel centres (Intrinsics::Ray) against the
// mesh, with lens distortion and anti-aliasing on.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "sim/render/renderer.h"
#include "tests/sim/render_test_scenes.h"

namespace avc::sim {
namespace {

using render_test::LookAt;

Scene SphereAndPlanes() {
  Scene scene;
  scene.name = "sphere and planes";
  scene.materials = {render_test::TexturedMaterial(1), render_test::TexturedMaterial(2)};
  geometry::Mesh& mesh = scene.mesh;
  render_test::AddSphere(&mesh, {0.0f, 0.0f, 0.08f}, 0.06f, 32, 16, 1, 0);
  // A tilted floor and a back wall, seen obliquely (strong depth gradients), with big faces
  // that distortion bends.
  render_test::AddQuad(&mesh, {-0.3f, -0.3f, 0.0f}, {0.6f, 0.0f, 0.02f}, {0.0f, 0.6f, -0.01f}, 6, 2,
                       1);
  render_test::AddQuad(&mesh, {-0.3f, 0.15f, 0.0f}, {0.6f, 0.0f, 0.0f}, {0.0f, 0.05f, 0.3f}, 4, 3,
                       1);
  render_test::LabelFacesByIndex(&mesh);
  return scene;
}

// Pixels between the ray's point on face's plane and the nearest point of the face's boundary.
double PixelsOutside(const camera::Camera& camera, const geometry::Mesh& mesh, int face,
                     const Eigen::Vector3d& origin, const Eigen::Vector3d& ray) {
  std::array<Eigen::Vector3d, 3> p;
  for (int k = 0; k < 3; ++k) p[k] = mesh.vertices[mesh.faces[face][k]].cast<double>();
  const Eigen::Vector3d n = (p[1] - p[0]).cross(p[2] - p[0]);
  const Eigen::Vector3d x = origin + n.dot(p[0] - origin) / n.dot(ray) * ray;
  double best = 1e30;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d d = p[(k + 1) % 3] - p[k];
    const double t = std::clamp((x - p[k]).dot(d) / d.squaredNorm(), 0.0, 1.0);
    const auto a = camera.Project(x), b = camera.Project(p[k] + t * d);
    if (a && b) best = std::min(best, (*a - *b).norm());
  }
  return best;
}

struct Agreement {
  int foreground = 0;               // sampled pixels where the ray hits the mesh
  int mismatches = 0;               // label differs from the hit face (or background)
  double worst_relative_depth = 0;  // over pixels where the label names the hit face
  double worst_mismatch_px = 0;     // of a mismatched pixel centre to the nearer face boundary
};

Agreement Compare(const Scene& scene, const camera::Camera& camera, const RenderResult& result,
                  int stride) {
  Agreement a;
  const Eigen::Vector3d centre = camera.Centre();
  const Eigen::Matrix3d R_world_cam = camera.T_cam_world.linear().transpose();
  const Eigen::Vector3d axis = camera.Axis();
  for (int v = 0; v < camera.intrinsics.height; v += stride) {
    for (int u = 0; u < camera.intrinsics.width; u += stride) {
      const Eigen::Vector3d ray = R_world_cam * camera.intrinsics.Ray(Eigen::Vector2d(u, v));
      const auto hit = render_test::CastRay(scene.mesh, centre, ray);
      const int32_t label = result.labels.at<int32_t>(v, u);
      const float depth = result.depth.at<float>(v, u);
      if (hit) ++a.foreground;
      if (hit && label == hit->face + 1) {
        const double z = hit->distance * ray.dot(axis);  // camera-frame z of the hit
        a.worst_relative_depth = std::max(a.worst_relative_depth, std::abs(depth - z) / z);
        continue;
      }
      if (!hit && label == 0 && depth == 0) continue;
      // Only a pixel centre on a face boundary (a shared edge or a silhouette) may go either way.
      ++a.mismatches;
      double distance = 1e30;
      if (hit) distance = PixelsOutside(camera, scene.mesh, hit->face, centre, ray);
      if (label != 0) {
        distance = std::min(distance, PixelsOutside(camera, scene.mesh, label - 1, centre, ray));
      }
      a.worst_mismatch_px = std::max(a.worst_mismatch_px, distance);
    }
  }
  return a;
}

void ExpectAgreement(const Agreement& a, int min_foreground) {
  ASSERT_GT(a.foreground, min_foreground) << "the scene should fill most of the image";
  // Float output: a few ulps. A single Newton step of undistortion was 2.6e-6 off.
  EXPECT_LT(a.worst_relative_depth, 1e-6);
  EXPECT_LT(a.mismatches, a.foreground / 200);
  EXPECT_LT(a.worst_mismatch_px, 0.06);
}

class RenderDepth : public ::testing::TestWithParam<int> {};

TEST_P(RenderDepth, MatchesRayCastThroughPixelCentres) {
  const Scene scene = SphereAndPlanes();
  camera::Camera camera;
  camera.intrinsics = render_test::TestIntrinsics(true, 320, 240);
  camera.T_cam_world = LookAt({0.25, -0.32, 0.2}, {0.0, 0.02, 0.06});
  RenderOptions options;
  options.samples_per_pixel_axis = GetParam();
  const RenderResult result = Render(scene, camera, options);
  // The default (2) everywhere; the others on every other pixel to keep the test quick.
  const int stride = GetParam() == 2 ? 1 : 2;
  ExpectAgreement(Compare(scene, camera, result, stride), 60000 / (stride * stride));
}

INSTANTIATE_TEST_SUITE_P(SamplesPerAxis, RenderDepth, ::testing::Values(1, 2, 3));

TEST(RenderDepthNoDistortion, MatchesRayCast) {
  const Scene scene = SphereAndPlanes();
  camera::Camera camera;
  camera.intrinsics = render_test::TestIntrinsics(false, 320, 240);
  camera.T_cam_world = LookAt({-0.3, -0.25, 0.25}, {0.0, 0.0, 0.05});
  const RenderResult result = Render(scene, camera, RenderOptions{});
  ExpectAgreement(Compare(scene, camera, result, 2), 15000);
}

}  // namespace
}  // namespace avc::sim
