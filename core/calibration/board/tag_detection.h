#pragma once

// AprilTag 36h11 markers (OpenCV contrib aruco) and their poses, for hand-eye data where the
// target is a single tag (the ViSP eye-to-hand set: id 10, 48 mm).
//
// Tag frame (OpenCV's aruco convention): origin at the tag centre, x to the right and y up as the
// tag is printed, z out of the tag towards the viewer. Corners come clockwise from the top-left.

#include <Eigen/Geometry>
#include <array>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/camera/pinhole_camera.h"

namespace avc::calibration {

struct TagDetection {
  int id = -1;
  std::array<cv::Point2f, 4> corners;  // top-left, top-right, bottom-right, bottom-left
};

struct TagPose {
  Eigen::Isometry3d T_cam_tag = Eigen::Isometry3d::Identity();
  double rms_px = 0;                   // corner reprojection RMS
  std::array<cv::Point2f, 4> corners;  // the detection's, TagCornerPoints order
};

// All 36h11 tags in an 8-bit grey or BGR image, sub-pixel corners, sorted by id. Throws
// std::invalid_argument naming `name` for an empty or unsupported image.
std::vector<TagDetection> DetectAprilTags36h11(const cv::Mat& image, const std::string& name);

// Board-frame corner coordinates of a tag with side `size` metres, in TagDetection order.
std::vector<cv::Point3f> TagCornerPoints(double size);

// The pose of tag `id` (side `size` metres) in the camera. Throws std::runtime_error naming
// `name` and the id when the tag is not seen, std::invalid_argument for bad size or intrinsics.
TagPose DetectTagPose(const cv::Mat& image, int id, double size,
                      const camera::Intrinsics& intrinsics, const std::string& name);

}  // namespace avc::calibration
