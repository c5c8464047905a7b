// The builder node's input decoding: image_t in every encoding and pixel format it takes gives
// the same BGR pixels, and corrupt or unusable images and cameras are refused by name.

#include "services/builder/node_inputs.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace avc::builder {
namespace {

cv::Mat TestPicture() {
  cv::Mat bgr(24, 32, CV_8UC3);
  for (int y = 0; y < bgr.rows; ++y) {
    for (int x = 0; x < bgr.cols; ++x) {
      bgr.at<cv::Vec3b>(y, x) = cv::Vec3b(static_cast<uint8_t>(8 * x), static_cast<uint8_t>(10 * y),
                                          static_cast<uint8_t>((x * y) % 256));
    }
  }
  return bgr;
}

avc::image_t Message(const std::string& id, const std::vector<uint8_t>& data, int8_t encoding,
                     int8_t format, int width, int height, int stride = 0) {
  avc::image_t image{};
  image.image_id = id;
  image.width = width;
  image.height = height;
  image.row_stride = stride;
  image.encoding = encoding;
  image.pixel_format = format;
  image.data = data;
  image.size = static_cast<int32_t>(data.size());
  return image;
}

std::string ErrorOf(const avc::image_t& image) {
  try {
    DecodeImage(image);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

double MaxDifference(const cv::Mat& a, const cv::Mat& b) {
  if (a.size() != b.size() || a.type() != b.type()) return 1e9;
  return cv::norm(a, b, cv::NORM_INF);
}

TEST(NodeInputs, DecodesPngAndEveryRawLayoutToTheSameBgr) {
  const cv::Mat bgr = TestPicture();
  std::vector<uint8_t> png;
  cv::imencode(".png", bgr, png);
  EXPECT_EQ(MaxDifference(DecodeImage(Message("a", png, avc::image_t::ENCODING_PNG,
                                              avc::image_t::PIXEL_BGR8, 32, 24)),
                          bgr),
            0);

  // RGB rows padded to 100 bytes.
  cv::Mat rgb;
  cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
  std::vector<uint8_t> padded(100 * 24, 0);
  for (int y = 0; y < 24; ++y) std::copy_n(rgb.ptr<uint8_t>(y), 96, padded.begin() + 100 * y);
  EXPECT_EQ(MaxDifference(DecodeImage(Message("b", padded, avc::image_t::ENCODING_RAW,
                                              avc::image_t::PIXEL_RGB8, 32, 24, 100)),
                          bgr),
            0);

  cv::Mat gray;
  cv::cvtColor(bgr, gray, cv::COLOR_BGR2GRAY);
  const std::vector<uint8_t> gray_bytes(gray.datastart, gray.dataend);
  cv::Mat gray_bgr;
  cv::cvtColor(gray, gray_bgr, cv::COLOR_GRAY2BGR);
  EXPECT_EQ(MaxDifference(DecodeImage(Message("c", gray_bytes, avc::image_t::ENCODING_RAW,
                                              avc::image_t::PIXEL_GRAY8, 32, 24)),
                          gray_bgr),
            0);
}

TEST(NodeInputs, RefusesCorruptOrUnusableImagesNamingThem) {
  const cv::Mat bgr = TestPicture();
  std::vector<uint8_t> png;
  cv::imencode(".png", bgr, png);
  std::vector<uint8_t> garbage(png.size(), 0x5a);
  EXPECT_NE(ErrorOf(Message("view_7", garbage, avc::image_t::ENCODING_PNG, avc::image_t::PIXEL_BGR8,
                            32, 24))
                .find("image 'view_7': its"),
            std::string::npos);
  EXPECT_NE(ErrorOf(Message("v", png, avc::image_t::ENCODING_PNG, avc::image_t::PIXEL_BGR8, 64, 48))
                .find("declared 64x48 but decodes to 32x24"),
            std::string::npos);
  EXPECT_NE(
      ErrorOf(Message("v", png, avc::image_t::ENCODING_PNG, avc::image_t::PIXEL_DEPTH32F, 32, 24))
          .find("pixel format 4"),
      std::string::npos);
  EXPECT_NE(ErrorOf(Message("v", png, 9, avc::image_t::PIXEL_BGR8, 32, 24)).find("encoding 9"),
            std::string::npos);
  EXPECT_NE(ErrorOf(Message("v", std::vector<uint8_t>(100), avc::image_t::ENCODING_RAW,
                            avc::image_t::PIXEL_BGR8, 32, 24))
                .find("do not fit"),
            std::string::npos);
  EXPECT_NE(ErrorOf(Message("v", {}, avc::image_t::ENCODING_JPEG, avc::image_t::PIXEL_BGR8, 32, 24))
                .find("do not decode"),
            std::string::npos);
}

avc::camera_t GoodCamera() {
  avc::camera_t camera{};
  camera.image_id = "view_3";
  camera.width = 320;
  camera.height = 240;
  camera.fx = camera.fy = 400;
  camera.cx = 159.5;
  camera.cy = 119.5;
  camera.distortion[0] = -0.1;
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) camera.T_cam_world[4 * r + c] = rotation(r, c);
    camera.T_cam_world[4 * r + 3] = std::array{0.1, 0.2, 0.3}[static_cast<size_t>(r)];
  }
  camera.T_cam_world[15] = 1;
  return camera;
}

std::string ErrorOf(const avc::camera_t& camera) {
  try {
    CameraFromMessage(camera);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

TEST(NodeInputs, TakesRigidCamerasAndRefusesBadOnesByField) {
  const camera::Camera camera = CameraFromMessage(GoodCamera());
  EXPECT_EQ(camera.intrinsics.width, 320);
  EXPECT_EQ(camera.intrinsics.distortion[0], -0.1);
  EXPECT_EQ(camera.T_cam_world.translation(), Eigen::Vector3d(0.1, 0.2, 0.3));

  avc::camera_t bad = GoodCamera();
  bad.fx = std::nan("");
  EXPECT_NE(ErrorOf(bad).find("camera of image 'view_3': focal"), std::string::npos)
      << ErrorOf(bad);
  bad = GoodCamera();
  bad.fy = INFINITY;
  EXPECT_NE(ErrorOf(bad).find("focal lengths are not finite"), std::string::npos);
  bad = GoodCamera();
  bad.width = 0;
  EXPECT_NE(ErrorOf(bad).find("image size 0x240"), std::string::npos);
  bad = GoodCamera();
  bad.distortion[4] = std::nan("");
  EXPECT_NE(ErrorOf(bad).find("distortion"), std::string::npos);
  bad = GoodCamera();
  bad.T_cam_world[7] = std::nan("");
  EXPECT_NE(ErrorOf(bad).find("T_cam_world is not finite"), std::string::npos);
  bad = GoodCamera();
  for (int c = 0; c < 3; ++c) bad.T_cam_world[c] *= 1.01;  // scaled row
  EXPECT_NE(ErrorOf(bad).find("not a rigid transform"), std::string::npos);
  bad = GoodCamera();
  for (int c = 0; c < 3; ++c) bad.T_cam_world[c] = -bad.T_cam_world[c];  // a reflection
  EXPECT_NE(ErrorOf(bad).find("not a rigid transform"), std::string::npos);
  bad = GoodCamera();
  bad.T_cam_world[12] = 0.5;
  EXPECT_NE(ErrorOf(bad).find("not a rigid transform"), std::string::npos);
}

}  // namespace
}  // namespace avc::builder
