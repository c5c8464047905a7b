#pragma once

// Reads a ViSP camera file (vpXmlParserCamera XML: image_width, image_height, px, py, u0, v0 of
// the perspective model; kud/kdu radial terms must be zero, as in the ViSP hand-eye data).

#include <filesystem>

#include "core/camera/pinhole_camera.h"

namespace avc::calibration {

// Throws std::runtime_error naming the file and the missing or bad field.
camera::Intrinsics ReadVispCameraXml(const std::filesystem::path& path);

}  // namespace avc::calibration
