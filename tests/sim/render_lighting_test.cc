// Lambert + ambient lighting: a face turned away from the light is darker by the cosine, both
// sides of a sheet are lit alike, and the output is sRGB-encoded.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "sim/render/renderer.h"
#include "tests/sim/render_test_scenes.h"

namespace avc::sim {
namespace {

using render_test::AddQuad;

constexpr float kAmbient = 0.2f, kDiffuse = 0.8f;

double DecodeSrgb(double code) {
  const double v = code / 255.0;
  return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

// Mean linear radiance (per BGR channel) of a 7x7 block around the image of a world point.
cv::Vec3d LinearAt(const RenderResult& result, const camera::Camera& camera,
                   const Eigen::Vector3d& world, bool srgb = true) {
  const Eigen::Vector2d pixel = *camera.Project(world);
  cv::Vec3d sum(0, 0, 0);
  for (int dv = -3; dv <= 3; ++dv) {
    for (int du = -3; du <= 3; ++du) {
      const cv::Vec3b c = result.color.at<cv::Vec3b>(static_cast<int>(std::lround(pixel.y())) + dv,
                                                     static_cast<int>(std::lround(pixel.x())) + du);
      for (int k = 0; k < 3; ++k) sum[k] += srgb ? DecodeSrgb(c[k]) : c[k] / 255.0;
    }
  }
  return sum / 49.0;
}

struct Fixture {
  Scene scene;
  camera::Camera camera;
  RenderOptions options;
  Eigen::Vector3f albedo;
};

// Seen from straight above with the light at the camera: a flat square (cos 1), one tilted by
// 60 degrees (cos 0.5), and a flat square facing away from the camera (its back side is seen).
Fixture Squares() {
  Fixture f;
  f.scene.name = "squares";
  f.scene.materials = {render_test::UniformMaterial({0.6f, 0.45f, 0.3f})};
  f.albedo = Albedo(f.scene.materials[0], {0.3f, 0.7f});
  const float c = 0.05f, s = 0.05f * std::sqrt(3.0f);
  AddQuad(&f.scene.mesh, {-0.2f, -0.05f, 0}, {0.1f, 0, 0}, {0, 0.1f, 0}, 2, 1, 0);
  AddQuad(&f.scene.mesh, {-0.05f, -0.05f, 0}, {c, 0, s}, {0, 0.1f, 0}, 2, 2, 0);
  AddQuad(&f.scene.mesh, {0.1f, -0.05f, 0}, {0, 0.1f, 0}, {0.1f, 0, 0}, 2, 3, 0);  // reversed
  f.camera.intrinsics = render_test::TestIntrinsics(true);
  f.camera.T_cam_world = render_test::LookAt({0, 0, 0.6}, {0, 0, 0}, Eigen::Vector3d::UnitY());
  f.options.ambient = kAmbient;
  f.options.diffuse = kDiffuse;
  f.options.light_direction = {0, 0, -1};  // towards the camera, in the camera frame
  return f;
}

void ExpectRadiance(const cv::Vec3d& measured, const Eigen::Vector3f& albedo, double cosine,
                    const char* what) {
  const double factor = kAmbient + kDiffuse * cosine;
  for (int k = 0; k < 3; ++k) {
    // BGR in the image, RGB in the albedo; 8-bit codes allow ~1%.
    EXPECT_NEAR(measured[2 - k], albedo[k] * factor, 0.012 * albedo[k] * factor + 0.002)
        << what << " channel " << k;
  }
}

TEST(RenderLighting, LambertCosineWithAmbient) {
  const Fixture f = Squares();
  const RenderResult result = Render(f.scene, f.camera, f.options);
  const cv::Vec3d flat = LinearAt(result, f.camera, {-0.15, 0, 0});
  const cv::Vec3d tilted = LinearAt(result, f.camera, {-0.05 + 0.025, 0, 0.025 * std::sqrt(3.0)});
  const cv::Vec3d back = LinearAt(result, f.camera, {0.15, 0, 0});
  ExpectRadiance(flat, f.albedo, 1.0, "flat");
  ExpectRadiance(tilted, f.albedo, 0.5, "tilted 60 degrees");
  ExpectRadiance(back, f.albedo, 1.0, "back side");
  EXPECT_LT(tilted[1], 0.75 * flat[1]) << "the face turned away from the light must be darker";
}

TEST(RenderLighting, WorldFrameLightGrazingTheFloorLeavesAmbient) {
  Fixture f = Squares();
  // Light along world x: the flat squares get only ambient light; the tilted one, whose normal
  // is (-sin 60, 0, cos 60), gets |n . l| = sin 60.
  f.options.light_direction = {1, 0, 0};
  f.options.light_in_world_frame = true;
  const RenderResult result = Render(f.scene, f.camera, f.options);
  ExpectRadiance(LinearAt(result, f.camera, {-0.15, 0, 0}), f.albedo, 0.0, "flat");
  ExpectRadiance(LinearAt(result, f.camera, {-0.05 + 0.025, 0, 0.025 * std::sqrt(3.0)}), f.albedo,
                 std::sqrt(3.0) / 2, "tilted");
}

TEST(RenderLighting, LinearOutputWithoutSrgb) {
  Fixture f = Squares();
  f.options.srgb = false;
  const RenderResult result = Render(f.scene, f.camera, f.options);
  ExpectRadiance(LinearAt(result, f.camera, {-0.15, 0, 0}, false), f.albedo, 1.0, "flat, linear");
}

TEST(RenderLighting, PlainBackgroundColour) {
  Fixture f = Squares();
  f.options.background.rgb = {0.1f, 0.2f, 0.4f};
  const RenderResult result = Render(f.scene, f.camera, f.options);
  const cv::Vec3b corner = result.color.at<cv::Vec3b>(2, 2);
  EXPECT_NEAR(DecodeSrgb(corner[0]), 0.4, 0.005);
  EXPECT_NEAR(DecodeSrgb(corner[1]), 0.2, 0.004);
  EXPECT_NEAR(DecodeSrgb(corner[2]), 0.1, 0.003);
}

TEST(RenderLighting, ClothBackgroundIsMottledAroundItsColour) {
  Fixture f = Squares();
  f.scene.mesh = geometry::Mesh{};
  f.options.background.kind = Background::Kind::kCloth;
  f.options.background.rgb = {0.3f, 0.3f, 0.3f};
  const RenderResult result = Render(f.scene, f.camera, f.options);
  double sum = 0, lo = 1, hi = 0;
  for (int v = 0; v < result.color.rows; v += 4) {
    for (int u = 0; u < result.color.cols; u += 4) {
      const double linear = DecodeSrgb(result.color.at<cv::Vec3b>(v, u)[1]);
      sum += linear, lo = std::min(lo, linear), hi = std::max(hi, linear);
    }
  }
  const double mean = sum / ((result.color.rows / 4) * (result.color.cols / 4));
  EXPECT_NEAR(mean, 0.3, 0.05);
  EXPECT_GT(hi - lo, 0.1) << "no mottling";
  EXPECT_LT(hi - lo, 0.3);
  // A backdrop fixed to world directions: turning the camera moves the pattern with the view.
  f.camera.T_cam_world = render_test::LookAt({0, 0, 0.6}, {0.05, 0, 0}, Eigen::Vector3d::UnitY());
  const RenderResult turned = Render(f.scene, f.camera, f.options);
  EXPECT_GT(cv::norm(result.color, turned.color, cv::NORM_L1), 0.0);
}

}  // namespace
}  // namespace avc::sim
