#include "core/mvs/patch/patch_image.h"

#include <Eigen/Dense>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace avc::mvs::patch {

PatchImage::PatchImage(const camera::Camera& camera, const cv::Mat& bgr, cv::Mat usable,
                       cv::Mat near, cv::Mat far)
    : camera_(camera), width_(bgr.cols), height_(bgr.rows) {
  has_depth_range_ = !near.empty();
  if (has_depth_range_) {
    // Keep only the rectangle the proxy covers (usable pixels lie inside it too): full-image
    // depths and masks cost 9 bytes a pixel in every view (0.9 GB for 72 views of 1616x1080)
    // where a thin plant covers a few per cent.
    cv::Mat covered = far > 0;
    usable_box_ = cv::boundingRect(covered);
    near_ = near(usable_box_).clone();
    far_ = far(usable_box_).clone();
    usable_ = usable(usable_box_).clone();
  } else {
    usable_box_ = cv::Rect(0, 0, width_, height_);
    usable_ = std::move(usable);
  }
  const auto& in = camera.intrinsics;
  Eigen::Matrix3d k;
  k << in.fx, 0, in.cx, 0, in.fy, in.cy, 0, 0, 1;
  m_ = k * camera.T_cam_world.linear();
  p4_ = k * camera.T_cam_world.translation();
  m_row3_ = m_.row(2).transpose();
  centre_ = camera.Centre();
  // Shared with the caller's image, not copied: a 72-view real scan's pixels are 377 MB.
  bgr_ = bgr.isContinuous() ? bgr : bgr.clone();
}

Eigen::Vector3d PatchImage::Ray(double u, double v) const {
  const Eigen::Vector3d ray_cam = camera_.intrinsics.Ray({u, v});
  return camera_.T_cam_world.linear().transpose() * ray_cam;
}

bool PatchImage::Usable(double u, double v) const {
  const int x = static_cast<int>(std::lround(u));
  const int y = static_cast<int>(std::lround(v));
  if (!usable_box_.contains(cv::Point(x, y))) return false;
  return usable_.at<uint8_t>(y - usable_box_.y, x - usable_box_.x) != 0;
}

std::pair<float, float> PatchImage::DepthRange(double u, double v) const {
  const int x = static_cast<int>(std::lround(u));
  const int y = static_cast<int>(std::lround(v));
  if (!has_depth_range_ || !usable_box_.contains(cv::Point(x, y))) return {0.f, 0.f};
  return {near_.at<float>(y - usable_box_.y, x - usable_box_.x),
          far_.at<float>(y - usable_box_.y, x - usable_box_.x)};
}

}  // namespace avc::mvs::patch
