#pragma once

// Where a set of cameras looks: the point nearest (least squares) to every optical axis. A
// scanning cell's cameras all look at the plant, so this is the scene's centre; the proxy's first
// box and the automatic choice of a dataset's length unit start from it.

#include <Eigen/Core>
#include <vector>

#include "core/camera/pinhole_camera.h"

namespace avc::camera {

// Throws std::invalid_argument with fewer than two cameras, a bad camera (naming it) or optical
// axes that are (nearly) parallel.
Eigen::Vector3d AxesMeetingPoint(const std::vector<Camera>& cameras);

}  // namespace avc::camera
