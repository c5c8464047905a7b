#pragma once

// Known camera intrinsics for `avc calibrate solve --intrinsics FILE`: an AVC calibration.yaml
// (its camera block), or an OpenCV calibration file (YAML or XML, as cv::FileStorage writes it)
// with camera_matrix and distortion_coefficients, and image_width and image_height when known.

#include <filesystem>

#include "core/camera/pinhole_camera.h"

namespace avc::calibration {

// The intrinsics in `path`; width and height are 0 when an OpenCV file does not give them (the
// solve then takes the images' size). Throws std::runtime_error naming the file and what is
// missing or unusable (a distortion model beyond k1 k2 p1 p2 k3, say).
camera::Intrinsics ReadIntrinsicsFile(const std::filesystem::path& path);

}  // namespace avc::calibration
