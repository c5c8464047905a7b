#include "core/ppr/proxy_silhouette.h"

#include <algorithm>
#include <cmath>

namespace avc::ppr {

cv::Mat ProxySilhouette(const mvs::MvsBounds& proxy, const camera::Camera& camera) {
  const auto& k = camera.intrinsics;
  cv::Mat silhouette = cv::Mat::zeros(k.height, k.width, CV_8UC1);
  const double radius = 0.5 * std::sqrt(3.0) * proxy.voxel_size;  // bounding sphere
  for (const Eigen::Vector3f& centre : proxy.occupied_centres) {
    const Eigen::Vector3d p = camera.T_cam_world * centre.cast<double>();
    if (p.z() <= radius) continue;
    const std::optional<Eigen::Vector2d> pixel = k.Project(p);
    if (!pixel) continue;
    const double half = radius * std::max(k.fx, k.fy) / (p.z() - radius);
    const int u0 = std::max(0, static_cast<int>(std::floor(pixel->x() - half)));
    const int u1 = std::min(k.width - 1, static_cast<int>(std::ceil(pixel->x() + half)));
    const int v0 = std::max(0, static_cast<int>(std::floor(pixel->y() - half)));
    const int v1 = std::min(k.height - 1, static_cast<int>(std::ceil(pixel->y() + half)));
    for (int v = v0; v <= v1; ++v) {
      uint8_t* row = silhouette.ptr<uint8_t>(v);
      std::fill(row + u0, row + std::max(u0, u1 + 1), uint8_t{255});
    }
  }
  return silhouette;
}

}  // namespace avc::ppr
