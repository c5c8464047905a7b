#pragma once

// Board poses from corner detections: conversions between OpenCV's (rvec, tvec) and T_cam_board,
// and solvePnP with fixed intrinsics (the A_i of hand-eye calibration).

#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <vector>

#include "core/camera/pinhole_camera.h"

namespace avc::calibration {

// OpenCV camera matrix and distortion (k1 k2 p1 p2 k3) of `intrinsics`, as CV_64F.
cv::Mat CameraMatrix(const camera::Intrinsics& intrinsics);
cv::Mat DistortionVector(const camera::Intrinsics& intrinsics);

// T_cam_board from OpenCV's board-to-camera rotation vector and translation (3x1 CV_64F).
Eigen::Isometry3d PoseFromRvecTvec(const cv::Mat& rvec, const cv::Mat& tvec);

struct BoardPose {
  Eigen::Isometry3d T_cam_board = Eigen::Isometry3d::Identity();
  double rms_px = 0;  // reprojection RMS of the corners at this pose
};

// The board pose that best reprojects `object_points` (board frame) onto `image_points`: IPPE
// for the planar start, then Levenberg-Marquardt. Throws std::invalid_argument naming `name` for
// mismatched sizes, fewer than 4 points, non-finite points or unusable intrinsics, and
// std::runtime_error when PnP fails.
BoardPose EstimateBoardPose(const std::vector<cv::Point3f>& object_points,
                            const std::vector<cv::Point2f>& image_points,
                            const camera::Intrinsics& intrinsics, const std::string& name);

// Root-mean-square pixel distance between `image_points` and the projection of `object_points`
// at T_cam_board.
double ReprojectionRms(const std::vector<cv::Point3f>& object_points,
                       const std::vector<cv::Point2f>& image_points,
                       const camera::Intrinsics& intrinsics, const Eigen::Isometry3d& T_cam_board);

}  // namespace avc::calibration
