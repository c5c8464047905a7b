#include "core/mvs/depth_range.h"

#include <algorithm>
#include <cmath>

namespace avc::mvs {

DepthRange ComputeDepthRange(const camera::Camera& camera, const MvsBounds& bounds, double margin) {
  const auto& k = camera.intrinsics;
  DepthRange range;
  range.near_depth = cv::Mat(k.height, k.width, CV_32F, cv::Scalar(0));
  range.far_depth = cv::Mat(k.height, k.width, CV_32F, cv::Scalar(0));
  const double radius = bounds.voxel_size * std::sqrt(3.0) / 2;
  const Eigen::Matrix3d rotation = camera.T_cam_world.linear();
  const Eigen::Vector3d translation = camera.T_cam_world.translation();
  for (const Eigen::Vector3f& centre : bounds.occupied_centres) {
    const Eigen::Vector3d p = rotation * centre.cast<double>() + translation;
    if (p.z() <= radius) continue;
    const double u = k.fx * p.x() / p.z() + k.cx;
    const double v = k.fy * p.y() / p.z() + k.cy;
    const double reach = radius * std::max(k.fx, k.fy) / (p.z() - radius);
    const int u0 = std::max(0, static_cast<int>(std::floor(u - reach)));
    const int u1 = std::min(k.width - 1, static_cast<int>(std::ceil(u + reach)));
    const int v0 = std::max(0, static_cast<int>(std::floor(v - reach)));
    const int v1 = std::min(k.height - 1, static_cast<int>(std::ceil(v + reach)));
    const float near = static_cast<float>(std::max(1e-6, p.z() - radius - margin));
    const float far = static_cast<float>(p.z() + radius + margin);
    for (int y = v0; y <= v1; ++y) {
      float* near_row = range.near_depth.ptr<float>(y);
      float* far_row = range.far_depth.ptr<float>(y);
      for (int x = u0; x <= u1; ++x) {
        if (far_row[x] == 0 || near < near_row[x]) near_row[x] = near;
        far_row[x] = std::max(far_row[x], far);
      }
    }
  }
  return range;
}

}  // namespace avc::mvs
