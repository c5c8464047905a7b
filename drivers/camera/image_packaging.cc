#include "drivers/camera/image_packaging.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>

namespace avc::camera_driver {
namespace {

bool AlreadyEncodedAs(const CameraImage& image, int8_t encoding) {
  return (encoding == avc::image_t::ENCODING_JPEG && image.mime_type == "image/jpeg") ||
         (encoding == avc::image_t::ENCODING_PNG && image.mime_type == "image/png");
}

std::vector<uint8_t> Encode(const cv::Mat& pixels, const char* extension,
                            const std::vector<int>& parameters) {
  std::vector<uint8_t> out;
  if (!cv::imencode(extension, pixels, out, parameters)) {
    throw std::runtime_error(fmt::format("could not encode the image as {}", extension));
  }
  return out;
}

double ParseNumber(std::string_view text) {
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nan("");
  return value;
}

}  // namespace

avc::image_t PackageImage(const CameraImage& image, const ImageLabels& labels) {
  if (labels.encoding != avc::image_t::ENCODING_RAW &&
      labels.encoding != avc::image_t::ENCODING_PNG &&
      labels.encoding != avc::image_t::ENCODING_JPEG) {
    throw std::invalid_argument(fmt::format("unknown image encoding {}", labels.encoding));
  }
  const cv::Mat encoded(1, static_cast<int>(image.data.size()), CV_8UC1,
                        const_cast<uint8_t*>(image.data.data()));
  const cv::Mat pixels = image.data.empty() ? cv::Mat() : cv::imdecode(encoded, cv::IMREAD_COLOR);
  if (pixels.empty()) {
    throw CameraError(CameraError::Kind::kFailed,
                      fmt::format("the camera's file '{}' ({} bytes, {}) is not a readable image",
                                  image.file_name, image.data.size(), image.mime_type));
  }
  avc::image_t out{};
  out.image_id = labels.image_id;
  out.camera_id = labels.camera_id;
  out.width = pixels.cols;
  out.height = pixels.rows;
  out.encoding = labels.encoding;
  out.iso = labels.iso;
  out.exposure_us = labels.exposure_us;
  out.pixel_format = avc::image_t::PIXEL_BGR8;  // what the bytes decode to with OpenCV
  if (AlreadyEncodedAs(image, labels.encoding)) {
    out.data = image.data;
  } else if (labels.encoding == avc::image_t::ENCODING_PNG) {
    out.data = Encode(pixels, ".png", {cv::IMWRITE_PNG_COMPRESSION, 3});
  } else if (labels.encoding == avc::image_t::ENCODING_JPEG) {
    out.data = Encode(pixels, ".jpg", {cv::IMWRITE_JPEG_QUALITY, 95});
  } else {
    out.row_stride = static_cast<int32_t>(pixels.step[0]);
    out.data.assign(pixels.data, pixels.data + pixels.step[0] * pixels.rows);
  }
  out.size = static_cast<int32_t>(out.data.size());
  return out;
}

std::string ProductName(const std::string& folder, const avc::image_t& image) {
  const char* extension = image.encoding == avc::image_t::ENCODING_PNG    ? "png"
                          : image.encoding == avc::image_t::ENCODING_JPEG ? "jpg"
                                                                          : "bgr";
  return fmt::format("{}/{}.{}", folder, image.image_id, extension);
}

int64_t ShutterMicros(const std::string& shutterspeed) {
  const size_t slash = shutterspeed.find('/');
  double seconds = 0;
  if (slash == std::string::npos) {
    seconds = ParseNumber(shutterspeed);
  } else {
    const double numerator = ParseNumber(std::string_view(shutterspeed).substr(0, slash));
    const double denominator = ParseNumber(std::string_view(shutterspeed).substr(slash + 1));
    seconds = denominator > 0 ? numerator / denominator : std::nan("");
  }
  if (!std::isfinite(seconds) || seconds <= 0) return 0;
  return std::llround(seconds * 1e6);
}

}  // namespace avc::camera_driver
