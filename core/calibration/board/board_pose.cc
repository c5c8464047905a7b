#include "core/calibration/board/board_pose.h"

#include <fmt/format.h>

#include <cmath>
#include <opencv2/calib3d.hpp>
#include <stdexcept>

namespace avc::calibration {
namespace {

void RvecTvecFromPose(const Eigen::Isometry3d& T, cv::Mat& rvec, cv::Mat& tvec) {
  cv::Mat rotation(3, 3, CV_64F);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) rotation.at<double>(r, c) = T.linear()(r, c);
  }
  cv::Rodrigues(rotation, rvec);
  tvec = (cv::Mat_<double>(3, 1) << T.translation().x(), T.translation().y(), T.translation().z());
}

bool AllFinite(const std::vector<cv::Point2f>& points) {
  for (const auto& p : points) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
  }
  return true;
}

bool AllFinite(const std::vector<cv::Point3f>& points) {
  for (const auto& p : points) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return false;
  }
  return true;
}

}  // namespace

cv::Mat CameraMatrix(const camera::Intrinsics& intrinsics) {
  return (cv::Mat_<double>(3, 3) << intrinsics.fx, 0, intrinsics.cx, 0, intrinsics.fy,
          intrinsics.cy, 0, 0, 1);
}

cv::Mat DistortionVector(const camera::Intrinsics& intrinsics) {
  cv::Mat d(5, 1, CV_64F);
  for (int i = 0; i < 5; ++i) d.at<double>(i) = intrinsics.distortion[static_cast<size_t>(i)];
  return d;
}

Eigen::Isometry3d PoseFromRvecTvec(const cv::Mat& rvec, const cv::Mat& tvec) {
  if (rvec.total() != 3 || tvec.total() != 3)
    throw std::invalid_argument("rvec and tvec must have 3 elements each");
  cv::Mat rvec64, tvec64, rotation;
  rvec.convertTo(rvec64, CV_64F);
  tvec.convertTo(tvec64, CV_64F);
  cv::Rodrigues(rvec64.reshape(1, 3), rotation);
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) T.linear()(r, c) = rotation.at<double>(r, c);
    T.translation()(r) = tvec64.at<double>(r);
  }
  return T;
}

double ReprojectionRms(const std::vector<cv::Point3f>& object_points,
                       const std::vector<cv::Point2f>& image_points,
                       const camera::Intrinsics& intrinsics, const Eigen::Isometry3d& T_cam_board) {
  if (object_points.size() != image_points.size() || object_points.empty())
    throw std::invalid_argument("reprojection needs equally many, non-zero object/image points");
  cv::Mat rvec, tvec;
  RvecTvecFromPose(T_cam_board, rvec, tvec);
  std::vector<cv::Point2f> projected;
  cv::projectPoints(object_points, rvec, tvec, CameraMatrix(intrinsics),
                    DistortionVector(intrinsics), projected);
  double sum = 0;
  for (size_t i = 0; i < projected.size(); ++i) {
    const cv::Point2f d = projected[i] - image_points[i];
    sum += static_cast<double>(d.x) * d.x + static_cast<double>(d.y) * d.y;
  }
  return std::sqrt(sum / static_cast<double>(projected.size()));
}

BoardPose EstimateBoardPose(const std::vector<cv::Point3f>& object_points,
                            const std::vector<cv::Point2f>& image_points,
                            const camera::Intrinsics& intrinsics, const std::string& name) {
  if (object_points.size() != image_points.size())
    throw std::invalid_argument(fmt::format("board pose '{}': {} object points but {} image points",
                                            name, object_points.size(), image_points.size()));
  if (object_points.size() < 4)
    throw std::invalid_argument(fmt::format("board pose '{}': needs at least 4 points, got {}",
                                            name, object_points.size()));
  if (!AllFinite(object_points) || !AllFinite(image_points))
    throw std::invalid_argument(fmt::format("board pose '{}': a point is not finite", name));
  if (const std::string problem = intrinsics.Validate(); !problem.empty())
    throw std::invalid_argument(fmt::format("board pose '{}': intrinsics: {}", name, problem));
  const cv::Mat K = CameraMatrix(intrinsics);
  const cv::Mat dist = DistortionVector(intrinsics);
  cv::Mat rvec, tvec;
  bool planar = true;
  for (const auto& p : object_points) planar = planar && p.z == 0.f;
  const int method = planar ? cv::SOLVEPNP_IPPE : cv::SOLVEPNP_ITERATIVE;
  if (!cv::solvePnP(object_points, image_points, K, dist, rvec, tvec, false, method))
    throw std::runtime_error(fmt::format("board pose '{}': solvePnP failed", name));
  cv::solvePnPRefineLM(
      object_points, image_points, K, dist, rvec, tvec,
      cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 100, 1e-12));
  BoardPose pose;
  pose.T_cam_board = PoseFromRvecTvec(rvec, tvec);
  if (!pose.T_cam_board.matrix().allFinite() || !(pose.T_cam_board.translation().z() > 0))
    throw std::runtime_error(
        fmt::format("board pose '{}': no valid pose in front of the camera", name));
  pose.rms_px = ReprojectionRms(object_points, image_points, intrinsics, pose.T_cam_board);
  return pose;
}

}  // namespace avc::calibration
