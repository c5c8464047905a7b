#include "core/mvs/plane_sweep/sweep_depth_range.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/mvs/view_neighbours.h"

namespace avc::mvs {

SceneSphere CommonViewSphere(const std::vector<camera::Camera>& cameras) {
  SceneSphere sphere;
  sphere.centre = NearestPointToAxes(cameras);
  double radius = std::numeric_limits<double>::infinity();
  for (const camera::Camera& camera : cameras) {
    const camera::Intrinsics& k = camera.intrinsics;
    const Eigen::Vector3d p = camera.T_cam_world * sphere.centre;
    if (p.z() <= 0) continue;
    // Distance of the centre's projection ray to each image side plane, in the camera frame.
    const double left = std::atan2(k.cx + 0.5, k.fx);
    const double right = std::atan2(k.width - 0.5 - k.cx, k.fx);
    const double top = std::atan2(k.cy + 0.5, k.fy);
    const double bottom = std::atan2(k.height - 0.5 - k.cy, k.fy);
    const double horizontal = std::atan2(p.x(), p.z());
    const double vertical = std::atan2(p.y(), p.z());
    const double margin =
        std::min({left + horizontal, right - horizontal, top + vertical, bottom - vertical});
    radius = std::min(radius, p.norm() * std::sin(std::max(0.0, margin)));
  }
  sphere.radius = std::isfinite(radius) ? radius : 0;
  return sphere;
}

DepthRange SweepDepthRange(const SweepView& view, const MvsBounds& bounds,
                           const SceneSphere& sphere, double margin_voxels) {
  DepthRange range;
  if (!bounds.empty()) {
    range = ComputeDepthRange(view.camera, bounds, margin_voxels * bounds.voxel_size);
  } else {
    const camera::Intrinsics& k = view.camera.intrinsics;
    range.near_depth = cv::Mat(k.height, k.width, CV_32F, cv::Scalar(0));
    range.far_depth = cv::Mat(k.height, k.width, CV_32F, cv::Scalar(0));
    const Eigen::Vector3d c = view.camera.T_cam_world * sphere.centre;
    const double r2 = sphere.radius * sphere.radius;
    for (int y = 0; y < k.height; ++y) {
      float* near_row = range.near_depth.ptr<float>(y);
      float* far_row = range.far_depth.ptr<float>(y);
      for (int x = 0; x < k.width; ++x) {
        // Ray X = z (xn, yn, 1): solve |z d - c|^2 = r^2 for the depth z.
        const Eigen::Vector3d d((x - k.cx) / k.fx, (y - k.cy) / k.fy, 1.0);
        const double a = d.squaredNorm();
        const double b = d.dot(c);
        const double disc = b * b - a * (c.squaredNorm() - r2);
        if (disc <= 0) continue;
        const double near = (b - std::sqrt(disc)) / a;
        const double far = (b + std::sqrt(disc)) / a;
        if (far <= 0) continue;
        near_row[x] = static_cast<float>(std::max(near, 1e-6));
        far_row[x] = static_cast<float>(far);
      }
    }
  }
  range.near_depth.setTo(0, view.mask == 0);
  range.far_depth.setTo(0, view.mask == 0);
  return range;
}

}  // namespace avc::mvs
