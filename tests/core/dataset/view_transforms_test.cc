// Undistortion and pyramid levels keep image and camera consistent: a world point's dot lands
// where the changed camera projects the point.

#include "core/dataset/view_transforms.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

namespace avc::dataset {
namespace {

// In front of a camera at the origin, off-centre so that lens distortion moves it by pixels.
const Eigen::Vector3d kPoint(0.15, -0.09, 0.5);

View ViewWithDot(const std::array<double, 5>& distortion) {
  View view;
  view.name = "dot.png";
  auto& k = view.camera.intrinsics;
  k.width = 320;
  k.height = 240;
  k.fx = k.fy = 300;
  k.cx = 160.5;
  k.cy = 119.5;
  k.distortion = distortion;
  view.image = cv::Mat(240, 320, CV_8UC3, cv::Scalar(0, 0, 0));
  view.mask = cv::Mat(240, 320, CV_8UC1, cv::Scalar(0));
  const Eigen::Vector2d pixel = *view.camera.Project(kPoint);
  // A smooth blob so that its intensity centroid is sub-pixel accurate after resampling.
  for (int v = 0; v < 240; ++v) {
    for (int u = 0; u < 320; ++u) {
      const double d2 = (Eigen::Vector2d(u, v) - pixel).squaredNorm();
      const auto value = static_cast<uint8_t>(std::lround(255 * std::exp(-d2 / (2 * 3.0 * 3.0))));
      view.image.at<cv::Vec3b>(v, u) = cv::Vec3b(value, value, value);
      if (d2 < 36) view.mask.at<uint8_t>(v, u) = 255;
    }
  }
  return view;
}

Eigen::Vector2d Centroid(const cv::Mat& bgr) {
  cv::Mat grey;
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  const cv::Moments m = cv::moments(grey);
  return {m.m10 / m.m00, m.m01 / m.m00};
}

TEST(ViewTransforms, PyramidLevelsHalveImageAndCameraTogether) {
  const View view = ViewWithDot({});
  const Eigen::Vector2d original = *view.camera.Project(kPoint);
  for (int level : {1, 2}) {
    const View smaller = AtPyramidLevel(view, level);
    const double scale = 1.0 / (1 << level);
    EXPECT_EQ(smaller.image.cols, 320 >> level);
    EXPECT_EQ(smaller.mask.rows, 240 >> level);
    EXPECT_EQ(smaller.camera.intrinsics.width, 320 >> level);
    const Eigen::Vector2d projected = *smaller.camera.Project(kPoint);
    EXPECT_NEAR((projected - original * scale).norm(), 0, 1e-9);
    EXPECT_LT((Centroid(smaller.image) - projected).norm(), 0.1) << "level " << level;
  }
  EXPECT_EQ(AtPyramidLevel(view, 0).image.data, view.image.data);  // level 0 shares pixels
  EXPECT_THROW(AtPyramidLevel(view, -1), std::invalid_argument);
  EXPECT_THROW(AtPyramidLevel(view, 5), std::invalid_argument);  // 10x7 pixels
}

TEST(ViewTransforms, UndistortMovesPixelsToThePinholeProjection) {
  View view = ViewWithDot({-0.25, 0.05, 0.001, -0.002, 0});
  const Eigen::Vector2d distorted = *view.camera.Project(kPoint);
  Undistort(view);
  EXPECT_FALSE(view.camera.intrinsics.HasDistortion());
  const Eigen::Vector2d pinhole = *view.camera.Project(kPoint);
  ASSERT_GT((pinhole - distorted).norm(), 2.0);  // the test moves the dot measurably
  EXPECT_LT((Centroid(view.image) - pinhole).norm(), 0.15);
  cv::Mat points;
  cv::findNonZero(view.mask, points);
  const cv::Scalar mask_centre = cv::mean(points);
  EXPECT_LT((Eigen::Vector2d(mask_centre[0], mask_centre[1]) - pinhole).norm(), 0.6);

  View plain = ViewWithDot({});
  const uchar* before = plain.image.data;
  Undistort(plain);
  EXPECT_EQ(plain.image.data, before);  // nothing to do, nothing copied
}

}  // namespace
}  // namespace avc::dataset
