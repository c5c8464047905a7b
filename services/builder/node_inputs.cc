#include "services/builder/node_inputs.h"

#include <fmt/format.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace avc::builder {
namespace {

cv::Mat DecodeRaw(const avc::image_t& image) {
  const bool gray = image.pixel_format == avc::image_t::PIXEL_GRAY8;
  const int channels = gray ? 1 : 3;
  const int64_t row_bytes = static_cast<int64_t>(image.width) * channels;
  const int64_t stride = image.row_stride > 0 ? image.row_stride : row_bytes;
  if (image.width <= 0 || image.height <= 0 || stride < row_bytes ||
      stride * image.height > static_cast<int64_t>(image.data.size())) {
    throw std::invalid_argument(fmt::format(
        "image '{}': {}x{} raw pixels with row stride {} do not fit its {} bytes", image.image_id,
        image.width, image.height, image.row_stride, image.data.size()));
  }
  const cv::Mat rows(image.height, image.width, gray ? CV_8UC1 : CV_8UC3,
                     const_cast<uint8_t*>(image.data.data()), static_cast<size_t>(stride));
  cv::Mat bgr;
  if (gray) {
    cv::cvtColor(rows, bgr, cv::COLOR_GRAY2BGR);
  } else if (image.pixel_format == avc::image_t::PIXEL_RGB8) {
    cv::cvtColor(rows, bgr, cv::COLOR_RGB2BGR);
  } else {
    bgr = rows.clone();
  }
  return bgr;
}

}  // namespace

cv::Mat DecodeImage(const avc::image_t& image) {
  const int8_t format = image.pixel_format;
  if (format != avc::image_t::PIXEL_GRAY8 && format != avc::image_t::PIXEL_RGB8 &&
      format != avc::image_t::PIXEL_BGR8) {
    throw std::invalid_argument(fmt::format(
        "image '{}': pixel format {} is not a colour or grey photograph", image.image_id, format));
  }
  if (image.size != static_cast<int32_t>(image.data.size())) {
    throw std::invalid_argument(fmt::format("image '{}': size {} but {} data bytes", image.image_id,
                                            image.size, image.data.size()));
  }
  cv::Mat bgr;
  if (image.encoding == avc::image_t::ENCODING_RAW) {
    bgr = DecodeRaw(image);
  } else if (image.encoding == avc::image_t::ENCODING_PNG ||
             image.encoding == avc::image_t::ENCODING_JPEG) {
    if (!image.data.empty()) {
      const cv::Mat encoded(1, static_cast<int>(image.data.size()), CV_8UC1,
                            const_cast<uint8_t*>(image.data.data()));
      bgr = cv::imdecode(encoded, cv::IMREAD_COLOR);
    }
    if (bgr.empty()) {
      throw std::invalid_argument(fmt::format(
          "image '{}': its {} bytes of {} do not decode", image.image_id, image.data.size(),
          image.encoding == avc::image_t::ENCODING_PNG ? "PNG" : "JPEG"));
    }
  } else {
    throw std::invalid_argument(
        fmt::format("image '{}': unknown encoding {}", image.image_id, image.encoding));
  }
  if (bgr.cols != image.width || bgr.rows != image.height) {
    throw std::invalid_argument(fmt::format("image '{}': declared {}x{} but decodes to {}x{}",
                                            image.image_id, image.width, image.height, bgr.cols,
                                            bgr.rows));
  }
  return bgr;
}

}  // namespace avc::builder
