// Same scene, camera and options give the same bytes: twice in a row, and with one thread or two.

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cstring>

#include "sim/render/renderer.h"
#include "sim/scene/plant.h"
#include "tests/sim/render_test_scenes.h"

namespace avc::sim {
namespace {

bool SameBytes(const cv::Mat& a, const cv::Mat& b) {
  return a.type() == b.type() && a.size() == b.size() && a.isContinuous() && b.isContinuous() &&
         std::memcmp(a.data, b.data, a.total() * a.elemSize()) == 0;
}

void ExpectSame(const RenderResult& a, const RenderResult& b, const char* what) {
  EXPECT_TRUE(SameBytes(a.color, b.color)) << what << ": colour differs";
  EXPECT_TRUE(SameBytes(a.depth, b.depth)) << what << ": depth differs";
  EXPECT_TRUE(SameBytes(a.labels, b.labels)) << what << ": labels differ";
}

Scene ManyObjects() {
  Scene scene;
  scene.name = "many objects";
  scene.materials = {render_test::TexturedMaterial(7), render_test::TexturedMaterial(8)};
  // Overlapping spheres (many tiles, many depth ties at their touching points) on a floor.
  for (int i = 0; i < 12; ++i) {
    const float a = 0.5f * static_cast<float>(i);
    render_test::AddSphere(&scene.mesh,
                           {0.08f * std::cos(a), 0.08f * std::sin(a), 0.03f + 0.005f * i}, 0.04f,
                           24, 12, 10 + i, i % 2);
  }
  render_test::AddQuad(&scene.mesh, {-0.3f, -0.3f, 0}, {0.6f, 0, 0}, {0, 0.6f, 0}, 8, 2, 1);
  return scene;
}

TEST(RenderDeterminism, SameBytesForOneAndTwoThreads) {
  const Scene scene = ManyObjects();
  camera::Camera camera;
  camera.intrinsics = render_test::TestIntrinsics(true);
  camera.T_cam_world = render_test::LookAt({0.3, -0.35, 0.3}, {0, 0, 0.03});
  RenderOptions options;
  options.background.kind = Background::Kind::kCloth;
  options.background.seed = 3;
  RenderResult one, two, again;
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    one = Render(scene, camera, options);
  }
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
    two = Render(scene, camera, options);
    again = Render(scene, camera, options);
  }
  ASSERT_GT(cv::countNonZero(one.labels), 50000) << "the scene should fill much of the image";
  ExpectSame(one, two, "1 vs 2 threads");
  ExpectSame(two, again, "two runs");
}

TEST(RenderDeterminism, GeneratedPlantSameBytesForOneAndTwoThreads) {
  PlantOptions plant;
  plant.target_triangles = 8000;
  const Scene scene = GeneratePlant(PlantPreset::kBushy, 5, plant);
  camera::Camera camera;
  camera.intrinsics = render_test::TestIntrinsics(true, 320, 240);
  camera.T_cam_world = render_test::LookAt({0.45, -0.3, 0.35}, {0, 0, 0.12});
  RenderOptions options;
  options.samples_per_pixel_axis = 3;
  RenderResult one, two;
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    one = Render(scene, camera, options);
  }
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
    two = Render(scene, camera, options);
  }
  ASSERT_GT(cv::countNonZero(one.labels), 5000) << "the plant should be in view";
  ExpectSame(one, two, "plant, 1 vs 2 threads");
}

TEST(RenderDeterminism, ReusedRendererMatchesFreshRenders) {
  // Working memory and result images carried from frame to frame must not leak into the next.
  const Scene many = ManyObjects();
  PlantOptions plant;
  plant.target_triangles = 6000;
  const Scene bushy = GeneratePlant(PlantPreset::kBushy, 2, plant);
  camera::Camera camera;
  camera.intrinsics = render_test::TestIntrinsics(true, 320, 240);
  camera.T_cam_world = render_test::LookAt({0.3, -0.35, 0.3}, {0, 0, 0.05});
  RenderOptions options;
  options.background.kind = Background::Kind::kCloth;
  Renderer renderer;
  RenderResult frame;
  renderer.Render(many, camera, options, &frame);
  const RenderResult kept = frame;  // shares the images: the next frame must not overwrite them
  const RenderResult kept_copy{frame.color.clone(), frame.depth.clone(), frame.labels.clone(), {}};
  renderer.Render(bushy, camera, options, &frame);
  ExpectSame(frame, Render(bushy, camera, options), "second scene, reused renderer");
  ExpectSame(kept, kept_copy, "a kept earlier frame");
  options.samples_per_pixel_axis = 3;
  renderer.Render(many, camera, options, &frame);
  ExpectSame(frame, Render(many, camera, options), "first scene again, other options");
}

TEST(RenderDeterminism, OptionsAndSeedsChangeTheImage) {
  // The comparison above must be able to fail: other inputs give other bytes.
  const Scene scene = ManyObjects();
  camera::Camera camera;
  camera.intrinsics = render_test::TestIntrinsics(true, 320, 240);
  camera.T_cam_world = render_test::LookAt({0.3, -0.35, 0.3}, {0, 0, 0.03});
  RenderOptions options;
  options.background.kind = Background::Kind::kCloth;
  const RenderResult base = Render(scene, camera, options);
  options.background.seed = 1;
  const RenderResult reseeded = Render(scene, camera, options);
  EXPECT_FALSE(SameBytes(base.color, reseeded.color));
  EXPECT_TRUE(SameBytes(base.labels, reseeded.labels));
  camera.T_cam_world = render_test::LookAt({0.3, -0.35, 0.3001}, {0, 0, 0.03});
  const RenderResult moved = Render(scene, camera, options);
  EXPECT_FALSE(SameBytes(reseeded.depth, moved.depth));
}

}  // namespace
}  // namespace avc::sim
