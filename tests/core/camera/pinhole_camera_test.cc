// The camera model agrees with OpenCV's, and camera sets survive both file formats.

#include "core/camera/pinhole_camera.h"

#include <gtest/gtest.h>

#include <opencv2/calib3d.hpp>
#include <random>

#include "core/camera/camera_io.h"
#include "tests/support/test_support.h"

namespace avc::camera {
namespace {

Intrinsics CanonLike() {
  Intrinsics k;
  k.width = 1280;
  k.height = 960;
  k.fx = 1750.5;
  k.fy = 1748.25;
  k.cx = 641.3;
  k.cy = 478.9;
  k.distortion = {-0.12, 0.08, 0.0012, -0.0007, -0.02};
  return k;
}

Camera SomeCamera(double angle) {
  Camera camera;
  camera.intrinsics = CanonLike();
  camera.T_cam_world = Eigen::Translation3d(0.01, -0.02, 0.6) *
                       Eigen::AngleAxisd(angle, Eigen::Vector3d(0.2, 1, 0.1).normalized());
  return camera;
}

TEST(PinholeCamera, ProjectsLikeOpenCv) {
  const Camera camera = SomeCamera(0.3);
  const Intrinsics& k = camera.intrinsics;
  const cv::Mat K = (cv::Mat_<double>(3, 3) << k.fx, 0, k.cx, 0, k.fy, k.cy, 0, 0, 1);
  const cv::Mat dist(1, 5, CV_64F, const_cast<double*>(k.distortion.data()));
  const Eigen::Matrix3d R = camera.T_cam_world.rotation();
  cv::Mat rmat(3, 3, CV_64F), rvec;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) rmat.at<double>(r, c) = R(r, c);
  }
  cv::Rodrigues(rmat, rvec);
  const Eigen::Vector3d t = camera.T_cam_world.translation();
  const cv::Mat tvec = (cv::Mat_<double>(3, 1) << t.x(), t.y(), t.z());
  std::mt19937 rng(3);
  std::vector<cv::Point3d> points;
  for (int i = 0; i < 500; ++i) {
    auto u = [&] { return (static_cast<double>(rng()) / rng.max() - 0.5) * 0.4; };
    points.emplace_back(u(), u(), u());
  }
  std::vector<cv::Point2d> expected;
  cv::projectPoints(points, rvec, tvec, K, dist, expected);
  for (size_t i = 0; i < points.size(); ++i) {
    const auto pixel = camera.Project({points[i].x, points[i].y, points[i].z});
    ASSERT_TRUE(pixel.has_value());
    EXPECT_NEAR(pixel->x(), expected[i].x, 1e-9);
    EXPECT_NEAR(pixel->y(), expected[i].y, 1e-9);
  }
}

TEST(PinholeCamera, RayInvertsProjection) {
  const Intrinsics k = CanonLike();
  for (double u : {0.0, 100.5, 640.0, 1279.0}) {
    for (double v : {0.0, 333.3, 959.0}) {
      const Eigen::Vector3d ray = k.Ray({u, v});
      EXPECT_NEAR(ray.norm(), 1.0, 1e-12);
      const auto back = k.Project(ray * 0.7);
      ASSERT_TRUE(back.has_value());
      EXPECT_NEAR(back->x(), u, 1e-6);
      EXPECT_NEAR(back->y(), v, 1e-6);
    }
  }
  EXPECT_FALSE(k.Project({0, 0, -1}).has_value());
}

TEST(PinholeCamera, ValidateNamesTheProblem) {
  Intrinsics k = CanonLike();
  EXPECT_EQ(k.Validate(), "");
  k.fx = 0;
  EXPECT_NE(k.Validate().find("focal"), std::string::npos);
  k = CanonLike();
  k.width = -1;
  EXPECT_NE(k.Validate().find("size"), std::string::npos);
}

std::vector<NamedCamera> SomeViews() {
  std::vector<NamedCamera> views;
  for (int i = 0; i < 4; ++i)
    views.push_back({"view_000" + std::to_string(i) + ".png", SomeCamera(0.4 * i)});
  views[3].camera.intrinsics.distortion[4] = 0;  // a second COLMAP camera, OPENCV model
  return views;
}

TEST(CameraIo, JsonRoundTripIsExact) {
  testing::TempDir dir;
  const auto views = SomeViews();
  WriteCamerasJson(dir / "cameras.json", views);
  const auto back = ReadCamerasJson(dir / "cameras.json");
  ASSERT_EQ(back.size(), views.size());
  for (size_t i = 0; i < views.size(); ++i) {
    EXPECT_EQ(back[i].name, views[i].name);
    EXPECT_EQ(back[i].camera.intrinsics.distortion, views[i].camera.intrinsics.distortion);
    EXPECT_EQ(back[i].camera.intrinsics.fx, views[i].camera.intrinsics.fx);
    EXPECT_TRUE(back[i].camera.T_cam_world.matrix() == views[i].camera.T_cam_world.matrix());
  }
}

TEST(CameraIo, ColmapRoundTrip) {
  testing::TempDir dir;
  const auto views = SomeViews();
  WriteColmapText(dir.path(), views);
  const std::string cameras = testing::ReadFile(dir / "cameras.txt");
  EXPECT_NE(cameras.find("1 FULL_OPENCV 1280 960"), std::string::npos) << cameras;
  EXPECT_NE(cameras.find("2 OPENCV 1280 960"), std::string::npos) << cameras;
  const auto back = ReadColmapText(dir.path());
  ASSERT_EQ(back.size(), views.size());
  for (size_t i = 0; i < views.size(); ++i) {
    EXPECT_EQ(back[i].name, views[i].name);
    EXPECT_EQ(back[i].camera.intrinsics.distortion, views[i].camera.intrinsics.distortion);
    EXPECT_TRUE(
        back[i].camera.T_cam_world.matrix().isApprox(views[i].camera.T_cam_world.matrix(), 1e-12));
  }
}

TEST(CameraIo, BadFilesNameFileAndPlace) {
  testing::TempDir dir;
  testing::WriteFile(dir / "cameras.json", R"({"cameras": [{"width": 10}]})");
  try {
    ReadCamerasJson(dir / "cameras.json");
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cameras.json: camera 0"), std::string::npos) << e.what();
  }
  testing::WriteFile(dir / "cameras.txt", "# c\n1 KANNALA 10 10 1 2 3\n");
  testing::WriteFile(dir / "images.txt", "");
  try {
    ReadColmapText(dir.path());
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cameras.txt:2: camera model KANNALA"), std::string::npos)
        << e.what();
  }
  testing::WriteFile(dir / "cameras.txt", "1 PINHOLE 10 10 5 5 5 5\n");
  testing::WriteFile(dir / "images.txt", "1 1 0 0 0 0 0 0 7 a.png\n\n");
  EXPECT_THROW(ReadColmapText(dir.path()), std::runtime_error);
  EXPECT_THROW(ReadCamerasJson(dir / "missing.json"), std::runtime_error);
}

}  // namespace
}  // namespace avc::camera
