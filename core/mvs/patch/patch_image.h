#pragma once

// One input view as the patch MVS samples it: float RGB pixels for bilinear lookups, the
// projection matrix P = K[R|t], the pixels where the plant may be (mask ∩ proxy coverage) and
// the proxy's per-pixel depth interval.

#include <Eigen/Core>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "core/camera/pinhole_camera.h"

namespace avc::mvs::patch {

class PatchImage {
 public:
  // bgr: CV_8UC3; usable: CV_8UC1 of the same size, non-zero where a surface may be; near and
  // far: CV_32F depth interval per pixel (both empty when there is no proxy).
  PatchImage(const camera::Camera& camera, const cv::Mat& bgr, cv::Mat usable, cv::Mat near,
             cv::Mat far);

  int width() const { return width_; }
  int height() const { return height_; }
  const camera::Camera& camera() const { return camera_; }
  const Eigen::Vector3d& centre() const { return centre_; }
  double fx() const { return camera_.intrinsics.fx; }

  // Homogeneous pixel (u w, v w, w) of a world point; w is its depth along the optical axis.
  Eigen::Vector3d ProjectH(const Eigen::Vector3d& p) const { return m_ * p + p4_; }
  // The homogeneous image of a world direction (the derivative of ProjectH).
  Eigen::Vector3d ProjectDirection(const Eigen::Vector3d& d) const { return m_ * d; }
  double Depth(const Eigen::Vector3d& p) const { return m_row3_.dot(p) + p4_.z(); }
  // Unit world ray from the centre through pixel (u, v).
  Eigen::Vector3d Ray(double u, double v) const;

  // True when (u, v) lies at least `margin` pixels inside the image.
  bool Inside(double u, double v, double margin) const {
    return u >= margin && v >= margin && u <= width_ - 1 - margin && v <= height_ - 1 - margin;
  }
  // The nearest pixel is inside the image and usable.
  bool Usable(double u, double v) const;
  bool HasDepthRange() const { return has_depth_range_; }
  // Depth interval at the nearest pixel; {0, 0} where the proxy does not cover it.
  std::pair<float, float> DepthRange(double u, double v) const;

  // Bilinear RGB (0..255) at (u, v); the caller guarantees 0 <= u <= w-1 and 0 <= v <= h-1.
  void Sample(float u, float v, float* rgb) const {
    int x = static_cast<int>(u);
    int y = static_cast<int>(v);
    if (x > width_ - 2) x = width_ - 2;
    if (y > height_ - 2) y = height_ - 2;
    const float fx = u - x;
    const float fy = v - y;
    const uint8_t* p00 = bgr_.data + (static_cast<size_t>(y) * width_ + x) * 3;
    const uint8_t* p10 = p00 + static_cast<size_t>(width_) * 3;
    const float w00 = (1 - fx) * (1 - fy), w01 = fx * (1 - fy), w10 = (1 - fx) * fy, w11 = fx * fy;
    for (int c = 0; c < 3; ++c) {
      const int b = 2 - c;  // the pixels are B G R
      rgb[c] = w00 * static_cast<float>(p00[b]) + w01 * static_cast<float>(p00[b + 3]) +
               w10 * static_cast<float>(p10[b]) + w11 * static_cast<float>(p10[b + 3]);
    }
  }

 private:
  camera::Camera camera_;
  int width_ = 0, height_ = 0;
  Eigen::Matrix3d m_;   // K R
  Eigen::Vector3d p4_;  // K t
  Eigen::Vector3d m_row3_;
  Eigen::Vector3d centre_;
  // The view's B G R bytes, continuous: a quarter of the memory traffic of floats, and the same
  // samples (bytes are exact in float).
  cv::Mat bgr_;
  bool has_depth_range_ = false;
  // Where usable_, near_ and far_ lie in the image: the proxy's footprint, or the whole image.
  cv::Rect usable_box_;
  cv::Mat usable_, near_, far_;
};

}  // namespace avc::mvs::patch
