#pragma once

// Where a proxy's occupied voxels fall in a view: each voxel drawn as the square its bounding
// sphere projects to, so the silhouette never misses a voxel's footprint. Masks are cut to it
// where the proxy has removed what the masks took for plant (a support under the plant).

#include <opencv2/core/mat.hpp>

#include "core/camera/pinhole_camera.h"
#include "core/mvs/mvs_bounds.h"

namespace avc::ppr {

// CV_8UC1 of the camera's image size, 255 where an occupied voxel projects. The camera must be
// undistorted (pinhole).
cv::Mat ProxySilhouette(const mvs::MvsBounds& proxy, const camera::Camera& camera);

}  // namespace avc::ppr
