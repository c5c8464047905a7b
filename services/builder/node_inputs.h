#pragma once

// The builder node's image input as the reconstruction needs it: an image_t product decoded to
// a BGR picture. Throws std::invalid_argument naming the image and the field at fault, so one
// bad message is refused and the node goes on (cameras: core/messages/camera_message.h).

#include <avc/image_t.hpp>
#include <opencv2/core/mat.hpp>

namespace avc::builder {

// CV_8UC3 BGR of the image's declared size. PNG and JPEG are decoded (grey becomes BGR);
// RAW takes GRAY8, RGB8 or BGR8 rows of row_stride bytes (0 = packed). Other pixel formats
// (depth, labels, 16-bit) are refused: they are not photographs of the plant.
cv::Mat DecodeImage(const avc::image_t& image);

}  // namespace avc::builder
