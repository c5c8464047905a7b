#include "core/mvs/patch/patch_image.h"

#include <Eigen/Dense>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace avc::mvs::patch {

PatchImage::PatchImage(const camera::Camera& camera, const cv::Mat& bgr, cv::Mat usable,
                       cv::Mat near, cv::Mat far)
    : camera_(camera), width_(bgr.cols), height_(bgr.rows), usable_(std::move(usable)) {
  has_depth_range_ = !near.empty();
  if (has_depth_range_) {
    // Keep only the rectangle the proxy covers: full-image float depths cost 8 bytes a pixel
    // in every view (1 GB for 72 views of 1616x1080) where a thin plant covers a few per cent.
    cv::Mat covered = far > 0;
    depth_box_ = cv::boundingRect(covered);
    near_ = near(depth_box_).clone();
    far_ = far(depth_box_).clone();
  }
  const auto& in = camera.intrinsics;
  Eigen::Matrix3d k;
  k << in.fx, 0, in.cx, 0, in.fy, in.cy, 0, 0, 1;
  m_ = k * camera.T_cam_world.linear();
  p4_ = k * camera.T_cam_world.translation();
  m_row3_ = m_.row(2).transpose();
  centre_ = camera.Centre();
  rgb_.resize(static_cast<size_t>(width_) * height_ * 3);
  for (int y = 0; y < height_; ++y) {
    const uint8_t* row = bgr.ptr<uint8_t>(y);
    uint8_t* out = rgb_.data() + static_cast<size_t>(y) * width_ * 3;
    for (int x = 0; x < width_; ++x) {
      out[3 * x + 0] = row[3 * x + 2];
      out[3 * x + 1] = row[3 * x + 1];
      out[3 * x + 2] = row[3 * x + 0];
    }
  }
}

Eigen::Vector3d PatchImage::Ray(double u, double v) const {
  const Eigen::Vector3d ray_cam = camera_.intrinsics.Ray({u, v});
  return camera_.T_cam_world.linear().transpose() * ray_cam;
}

bool PatchImage::Usable(double u, double v) const {
  const int x = static_cast<int>(std::lround(u));
  const int y = static_cast<int>(std::lround(v));
  if (x < 0 || y < 0 || x >= width_ || y >= height_) return false;
  return usable_.at<uint8_t>(y, x) != 0;
}

std::pair<float, float> PatchImage::DepthRange(double u, double v) const {
  const int x = static_cast<int>(std::lround(u));
  const int y = static_cast<int>(std::lround(v));
  if (!depth_box_.contains(cv::Point(x, y))) return {0.f, 0.f};
  return {near_.at<float>(y - depth_box_.y, x - depth_box_.x),
          far_.at<float>(y - depth_box_.y, x - depth_box_.x)};
}

}  // namespace avc::mvs::patch
