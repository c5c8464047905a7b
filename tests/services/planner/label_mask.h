#pragma once

// A perfect plant mask for planner tests: the organ labels (stem, petiole, leaf) rendered at a
// quarter of the camera's size, which is fast, and scaled back up to the camera's size.

#include <opencv2/core/mat.hpp>

#include "core/camera/pinhole_camera.h"
#include "sim/scene/scene.h"

namespace avc::testing {

cv::Mat LabelMask(const sim::Scene& scene, const camera::Camera& camera);

}  // namespace avc::testing
