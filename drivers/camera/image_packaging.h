#pragma once

// From what the camera delivered to the image_t product a capture request asked for. A picture
// already in the requested encoding travels byte for byte as the camera made it (no second JPEG
// generation); otherwise it is decoded once and re-encoded (PNG, JPEG at quality 95, or raw BGR8).

#include <avc/image_t.hpp>
#include <string>

#include "drivers/camera/camera_backend.h"

namespace avc::camera_driver {

struct ImageLabels {
  std::string image_id;
  std::string camera_id;
  int8_t encoding = avc::image_t::ENCODING_JPEG;  // requested; image_t::ENCODING_*
  double iso = 0;                                 // as set on the camera, 0 = unknown
  int64_t exposure_us = 0;                        // as set on the camera, 0 = unknown
};

// Throws CameraError(kFailed) naming the file when the camera's bytes cannot be decoded, and
// std::invalid_argument for an unknown encoding.
avc::image_t PackageImage(const CameraImage& image, const ImageLabels& labels);

// "images/<id>.jpg" / ".png" / ".bgr" by encoding: the product's file-like name.
std::string ProductName(const std::string& folder, const avc::image_t& image);

// Exposure time in microseconds from a camera shutter string ("1/125", "0.5", "2"); 0 when it
// is not a number (e.g. "Bulb").
int64_t ShutterMicros(const std::string& shutterspeed);

}  // namespace avc::camera_driver
