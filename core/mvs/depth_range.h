#pragma once

// What the plant proxy says about depth in one image: for every pixel, the nearest and farthest
// depth (along the optical axis) at which an occupied voxel covers it. MVS searches for a
// surface only inside this interval and only at pixels it covers.

#include <opencv2/core/mat.hpp>

#include "core/camera/pinhole_camera.h"
#include "core/mvs/mvs_bounds.h"

namespace avc::mvs {

struct DepthRange {
  cv::Mat near_depth;  // CV_32F, metres; 0 where no voxel projects
  cv::Mat far_depth;   // CV_32F, metres; 0 where no voxel projects

  bool Covers(int u, int v) const { return far_depth.at<float>(v, u) > 0; }
};

// Splats every occupied voxel into the image as the square its bounding sphere covers, widened
// by `margin` metres in depth. Ignores lens distortion (the views are undistorted first).
DepthRange ComputeDepthRange(const camera::Camera& camera, const MvsBounds& bounds, double margin);

}  // namespace avc::mvs
