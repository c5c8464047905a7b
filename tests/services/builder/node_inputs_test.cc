// The builder node's image decoding: image_t in every encoding and pixel format it takes gives
// the same BGR pixels, and corrupt or unusable images are refused by name.

#include "services/builder/node_inputs.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace avc::builder
