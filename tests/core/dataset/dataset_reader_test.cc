// The dataset importers: Middlebury (real data), COLMAP text and scan directories written by our
// own writers, masks, and the errors a user meets with a broken directory.

#include "core/dataset/dataset_reader.h"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/camera/camera_io.h"
#include "tests/support/test_support.h"

namespace avc::dataset {
namespace {

namespace fs = std::filesystem;

fs::path Dino() { return testing::SharedDataDir() / "middlebury" / "dinoSparseRing"; }

camera::NamedCamera MakeCamera(const std::string& name, double angle) {
  camera::NamedCamera named;
  named.name = name;
  auto& k = named.camera.intrinsics;
  k.width = 64;
  k.height = 48;
  k.fx = k.fy = 60;
  k.cx = 31.5;
  k.cy = 23.5;
  // Looking at the origin from 0.5 m away on a horizontal ring.
  const Eigen::Vector3d centre(0.5 * std::cos(angle), 0.5 * std::sin(angle), 0.1);
  const Eigen::Vector3d z = (-centre).normalized();
  const Eigen::Vector3d x = z.cross(Eigen::Vector3d::UnitZ()).normalized();
  const Eigen::Vector3d y = z.cross(x);
  Eigen::Matrix3d r;
  r << x.transpose(), y.transpose(), z.transpose();
  named.camera.T_cam_world.linear() = r;
  named.camera.T_cam_world.translation() = -r * centre;
  return named;
}

cv::Mat Gradient(int seed) {
  cv::Mat image(48, 64, CV_8UC3);
  for (int v = 0; v < image.rows; ++v) {
    for (int u = 0; u < image.cols; ++u) {
      image.at<cv::Vec3b>(v, u) = cv::Vec3b(u * 4, v * 5, static_cast<uint8_t>(seed * 40));
    }
  }
  return image;
}

void WriteImages(const fs::path& dir, const std::vector<camera::NamedCamera>& cameras) {
  fs::create_directories(dir);
  for (size_t i = 0; i < cameras.size(); ++i) {
    ASSERT_TRUE(cv::imwrite((dir / cameras[i].name).string(), Gradient(static_cast<int>(i))));
  }
}

TEST(DatasetReader, ReadsTheMiddleburyDino) {
  const fs::path dino = Dino();
  if (!fs::exists(dino)) GTEST_SKIP() << "shared data not found at " << dino;
  EXPECT_EQ(DetectDatasetFormat(dino), "middlebury");
  const ViewSet set = ReadDataset(dino);
  ASSERT_EQ(set.views.size(), 16u);
  EXPECT_EQ(set.format, "middlebury");
  EXPECT_TRUE(set.ground_truth_mesh.empty());
  // The centre of the README's tight bounding box images near the object in every view.
  const Eigen::Vector3d box_centre(-0.0255, 0.0247, -0.0212);
  for (const View& view : set.views) {
    EXPECT_EQ(view.image.cols, 640);
    EXPECT_EQ(view.image.rows, 480);
    EXPECT_TRUE(view.mask.empty());
    const auto pixel = view.camera.Project(box_centre);
    ASSERT_TRUE(pixel.has_value()) << view.name;
    EXPECT_GT(pixel->x(), 150) << view.name;
    EXPECT_LT(pixel->x(), 490) << view.name;
    EXPECT_GT(pixel->y(), 100) << view.name;
    EXPECT_LT(pixel->y(), 380) << view.name;
    // The dino is bright on a black background: much of the window round the centre is dino.
    const cv::Rect window(static_cast<int>(pixel->x()) - 40, static_cast<int>(pixel->y()) - 40, 80,
                          80);
    cv::Mat grey;
    cv::cvtColor(view.image(window), grey, cv::COLOR_BGR2GRAY);
    EXPECT_GT(cv::countNonZero(grey > 0.19 * 255), 0.3 * window.area()) << view.name;
  }
  EXPECT_EQ(ReadDataset(dino, {.load_masks = true, .stride = 4}).views.size(), 4u);
}

TEST(DatasetReader, ReadsAScanDirectoryWithMasks) {
  testing::TempDir dir;
  const std::vector<camera::NamedCamera> cameras = {MakeCamera("a.png", 0), MakeCamera("b.png", 1)};
  camera::WriteCamerasJson(dir / "cameras.json", cameras);
  WriteImages(dir / "images", cameras);
  fs::create_directories(dir / "masks");
  cv::Mat mask(48, 64, CV_8UC1, cv::Scalar(0));
  cv::rectangle(mask, cv::Rect(10, 10, 20, 20), cv::Scalar(1), cv::FILLED);
  ASSERT_TRUE(cv::imwrite((dir / "masks" / "b.png").string(), mask));
  testing::WriteFile(dir / "gt_mesh.ply", "not read here");

  const ViewSet set = ReadDataset(dir.path());
  EXPECT_EQ(set.format, "scan");
  EXPECT_EQ(set.ground_truth_mesh, dir / "gt_mesh.ply");
  ASSERT_EQ(set.views.size(), 2u);
  EXPECT_EQ(set.views[0].name, "a.png");
  EXPECT_TRUE(set.views[0].mask.empty());
  ASSERT_FALSE(set.views[1].mask.empty());
  EXPECT_EQ(cv::countNonZero(set.views[1].mask), 400);  // any non-zero value is plant
  EXPECT_EQ(set.views[1].mask.at<uint8_t>(15, 15), 255);
  EXPECT_EQ(cv::norm(set.views[1].image, Gradient(1), cv::NORM_INF), 0);
  EXPECT_TRUE(set.views[1].camera.T_cam_world.isApprox(cameras[1].camera.T_cam_world, 1e-12));
  EXPECT_TRUE(ReadDataset(dir.path(), {.load_masks = false}).views[1].mask.empty());
}

TEST(DatasetReader, ReadsAColmapTextModelInItsUsualPlaces) {
  const std::vector<camera::NamedCamera> cameras = {MakeCamera("x.png", 0), MakeCamera("y.png", 2),
                                                    MakeCamera("z.png", 4)};
  for (const char* model : {".", "sparse", "sparse/0", "colmap"}) {
    testing::TempDir dir;
    camera::WriteColmapText(dir.path() / model, cameras);
    WriteImages(dir / "images", cameras);
    EXPECT_EQ(DetectDatasetFormat(dir.path()), "colmap") << model;
    const ViewSet set = ReadDataset(dir.path());
    ASSERT_EQ(set.views.size(), 3u) << model;
    EXPECT_EQ(set.views[2].name, "z.png");
    EXPECT_NEAR(set.views[2].camera.intrinsics.fx, 60, 1e-9);
    EXPECT_TRUE(set.views[2].camera.T_cam_world.isApprox(cameras[2].camera.T_cam_world, 1e-9));
  }
}

TEST(DatasetReader, NamesTheProblemInABrokenDirectory) {
  const auto message = [](const fs::path& dir) {
    try {
      ReadDataset(dir);
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  testing::TempDir empty;
  EXPECT_NE(message(empty.path()).find("no cameras.json"), std::string::npos);
  EXPECT_NE(message(empty / "missing").find("not a directory"), std::string::npos);

  testing::TempDir scan;
  const std::vector<camera::NamedCamera> cameras = {MakeCamera("a.png", 0), MakeCamera("b.png", 1)};
  camera::WriteCamerasJson(scan / "cameras.json", cameras);
  WriteImages(scan / "images", {cameras[0]});
  EXPECT_NE(message(scan.path()).find("b.png: image not found"), std::string::npos)
      << message(scan.path());
  ASSERT_TRUE(cv::imwrite((scan / "images" / "b.png").string(), cv::Mat(10, 10, CV_8UC3)));
  EXPECT_NE(message(scan.path()).find("is 10x10 but its camera is 64x48"), std::string::npos);
  testing::WriteFile(scan / "images" / "b.png", "not a png");
  EXPECT_NE(message(scan.path()).find("cannot be decoded"), std::string::npos);

  testing::TempDir middlebury;
  testing::WriteFile(middlebury / "set_par.txt",
                     "2\nim.png 1 0 0 0 1 0 0 0 1  1 0 0 0 1 0 0 0 1  0 0\n");
  EXPECT_NE(message(middlebury.path()).find("line 2: expected a name and 21 numbers"),
            std::string::npos)
      << message(middlebury.path());
  testing::WriteFile(middlebury / "set_par.txt",
                     "1\nim.png 1 0 0 0 1 0 0 0 1  1 0 0 0 1 0 0 0 2  0 0 0\n");
  EXPECT_NE(message(middlebury.path()).find("R is not a rotation"), std::string::npos);
  testing::WriteFile(middlebury / "set_par.txt",
                     "3\nim.png 1 0 0 0 1 0 0 0 1  1 0 0 0 1 0 0 0 1  0 0 0\n");
  EXPECT_NE(message(middlebury.path()).find("announces 3 images but lists 1"), std::string::npos);
}

}  // namespace
}  // namespace avc::dataset
