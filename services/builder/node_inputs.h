#pragma once

// The builder node's inputs as the reconstruction needs them: an image_t product decoded to a
// BGR picture, and a camera_t turned into a checked camera. Both throw std::invalid_argument
// naming the image and the field at fault, so one bad message is refused and the node goes on.

#include <avc/camera_t.hpp>
#include <avc/image_t.hpp>
#include <opencv2/core/mat.hpp>

#include "core/camera/pinhole_camera.h"

namespace avc::builder {

// CV_8UC3 BGR of the image's declared size. PNG and JPEG are decoded (grey becomes BGR);
// RAW takes GRAY8, RGB8 or BGR8 rows of row_stride bytes (0 = packed). Other pixel formats
// (depth, labels, 16-bit) are refused: they are not photographs of the plant.
cv::Mat DecodeImage(const avc::image_t& image);

// Intrinsics must pass Intrinsics::Validate with finite values, and T_cam_world must be a
// finite rigid transform (orthonormal rotation with determinant +1, last row 0 0 0 1).
camera::Camera CameraFromMessage(const avc::camera_t& message);

}  // namespace avc::builder
