// A simulated scan on disk: every file is there, the cameras agree with the rendered depth and
// labels, and the same options give the same bytes.

#include "sim/dataset/render_dataset.h"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "core/camera/camera_io.h"
#include "core/geometry/mesh_io.h"
#include "sim/render/renderer.h"
#include "tests/support/test_support.h"

namespace avc::sim {
namespace {

namespace fs = std::filesystem;

RenderDatasetOptions SmallScan(const fs::path& output) {
  RenderDatasetOptions options;
  options.preset = PlantPreset::kBroadleaf;
  options.plant_seed = 5;
  options.plant.target_triangles = 6000;
  options.views = 5;
  options.rings = 2;
  options.width = 320;
  options.height = 240;
  options.render.samples_per_pixel_axis = 1;
  options.noise = true;
  options.output = output;
  return options;
}

TEST(RenderDataset, WritesAConsistentScan) {
  testing::TempDir dir;
  const RenderDatasetOptions options = SmallScan(dir / "scan");
  const RenderDatasetSummary summary = RenderDataset(options);
  const Scene scene = GeneratePlant(options.preset, options.plant_seed, options.plant);
  EXPECT_EQ(summary.views, 5);
  for (const std::string& file : summary.files) {
    EXPECT_TRUE(fs::is_regular_file(dir / "scan" / file)) << file;
  }
  const auto cameras = camera::ReadCamerasJson(dir / "scan" / "cameras.json");
  const auto colmap = camera::ReadColmapText(dir / "scan" / "colmap");
  ASSERT_EQ(cameras.size(), 5u);
  ASSERT_EQ(colmap.size(), 5u);
  const geometry::Mesh gt = geometry::ReadMesh(dir / "scan" / "gt_mesh.ply");
  EXPECT_EQ(gt.faces.size(), summary.triangles);
  EXPECT_EQ(gt.vertices, scene.mesh.vertices);
  EXPECT_EQ(gt.face_labels, scene.mesh.face_labels);

  for (size_t v = 0; v < cameras.size(); ++v) {
    const camera::Camera& camera = cameras[v].camera;
    EXPECT_TRUE(colmap[v].camera.T_cam_world.isApprox(camera.T_cam_world, 1e-9));
    EXPECT_EQ(camera.intrinsics.width, 320);
    const std::string stem = fs::path(cameras[v].name).stem().string();
    const cv::Mat depth =
        cv::imread((dir / "scan" / "depth" / (stem + ".tiff")).string(), cv::IMREAD_UNCHANGED);
    const cv::Mat labels =
        cv::imread((dir / "scan" / "labels" / (stem + ".png")).string(), cv::IMREAD_UNCHANGED);
    ASSERT_EQ(depth.type(), CV_32F);
    ASSERT_EQ(labels.type(), CV_16U);
    // The plant fills a good part of the frame, centred.
    double covered = 0, sum_u = 0;
    for (int y = 0; y < labels.rows; ++y) {
      for (int x = 0; x < labels.cols; ++x) {
        if (labels.at<uint16_t>(y, x) != 0) ++covered, sum_u += x;
      }
    }
    EXPECT_GT(covered / labels.total(), 0.08) << stem;
    EXPECT_NEAR(sum_u / covered, camera.intrinsics.cx, 0.2 * labels.cols) << stem;
    // The files hold exactly what the written camera sees: rendering the same plant with the
    // camera read back from cameras.json gives the same depth and labels, bit for bit (the
    // renderer's own tests check depth and projection against ray casting and OpenCV).
    RenderOptions render = options.render;
    const RenderResult again = Render(scene, camera, render);
    EXPECT_EQ(cv::norm(again.depth, depth, cv::NORM_INF), 0) << stem;
    cv::Mat labels32;
    labels.convertTo(labels32, CV_32S);
    EXPECT_EQ(cv::norm(again.labels, labels32, cv::NORM_INF), 0) << stem;
  }
}

TEST(RenderDataset, SameOptionsSameBytes) {
  testing::TempDir dir;
  RenderDatasetOptions options = SmallScan(dir / "a");
  options.views = 2;
  options.rings = 1;
  const RenderDatasetSummary a = RenderDataset(options);
  options.output = dir / "b";
  RenderDataset(options);
  for (const std::string& file : a.files) {
    EXPECT_EQ(testing::ReadFile(dir / "a" / file), testing::ReadFile(dir / "b" / file)) << file;
  }
}

TEST(RenderDataset, RefusesBadRequests) {
  testing::TempDir dir;
  RenderDatasetOptions options = SmallScan(dir / "scan");
  options.views = 0;
  EXPECT_THROW(RenderDataset(options), std::invalid_argument);
  options = SmallScan(dir.path());
  testing::WriteFile(dir / "keep.txt", "mine");
  try {
    RenderDataset(options);
    FAIL() << "a non-empty output was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("not empty"), std::string::npos) << e.what();
  }
  EXPECT_EQ(testing::ReadFile(dir / "keep.txt"), "mine");
  options = SmallScan(dir / "far");
  options.distance = 3.0;  // beyond the UR5's reach
  try {
    RenderDataset(options);
    FAIL() << "an unreachable view was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot reach"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace avc::sim
