#pragma once

// Cameras on the bus: camera::Camera <-> camera_t (lcmtypes/avc/camera_t.lcm), the calibrated
// camera of one image that the calibrator publishes and the builder and planner read.

#include <avc/camera_t.hpp>
#include <string>

#include "core/camera/pinhole_camera.h"

namespace avc::messages {

avc::camera_t CameraToMessage(const camera::Camera& camera, const std::string& image_id,
                              const std::string& camera_id);

// Intrinsics must pass Intrinsics::Validate with finite values, and T_cam_world must be a
// finite rigid transform (orthonormal rotation with determinant +1, last row 0 0 0 1). Throws
// std::invalid_argument naming the image and the field at fault.
camera::Camera CameraFromMessage(const avc::camera_t& message);

}  // namespace avc::messages
