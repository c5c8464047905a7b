#include "core/camera/pinhole_camera.h"

#include <fmt/format.h>

#include <cmath>

namespace avc::camera {

Eigen::Vector2d Intrinsics::Distort(const Eigen::Vector2d& n) const {
  const auto& [k1, k2, p1, p2, k3] = distortion;
  const double x = n.x(), y = n.y();
  const double r2 = x * x + y * y;
  const double radial = 1 + r2 * (k1 + r2 * (k2 + r2 * k3));
  return {x * radial + 2 * p1 * x * y + p2 * (r2 + 2 * x * x),
          y * radial + p1 * (r2 + 2 * y * y) + 2 * p2 * x * y};
}

Eigen::Vector2d Intrinsics::Undistort(const Eigen::Vector2d& d) const {
  if (!HasDistortion()) return d;
  // The same fixed-point scheme as cv::undistortPoints, run until it settles.
  Eigen::Vector2d n = d;
  for (int i = 0; i < 50; ++i) {
    const Eigen::Vector2d error = Distort(n) - d;
    n -= error;
    if (error.squaredNorm() < 1e-24) break;
  }
  return n;
}

std::optional<Eigen::Vector2d> Intrinsics::Project(const Eigen::Vector3d& p) const {
  if (!(p.z() > 0)) return std::nullopt;
  const Eigen::Vector2d d = Distort({p.x() / p.z(), p.y() / p.z()});
  return Eigen::Vector2d(fx * d.x() + cx, fy * d.y() + cy);
}

Eigen::Vector3d Intrinsics::Ray(const Eigen::Vector2d& pixel) const {
  const Eigen::Vector2d n = Undistort({(pixel.x() - cx) / fx, (pixel.y() - cy) / fy});
  return Eigen::Vector3d(n.x(), n.y(), 1).normalized();
}

bool Intrinsics::HasDistortion() const {
  for (double c : distortion) {
    if (c != 0) return true;
  }
  return false;
}

std::string Intrinsics::Validate() const {
  if (width <= 0 || height <= 0)
    return fmt::format("image size {}x{} is not positive", width, height);
  if (!(fx > 0) || !(fy > 0))
    return fmt::format("focal lengths fx={} fy={} must be positive", fx, fy);
  if (!std::isfinite(cx) || !std::isfinite(cy)) return "principal point is not finite";
  for (double c : distortion) {
    if (!std::isfinite(c)) return "a distortion coefficient is not finite";
  }
  return {};
}

}  // namespace avc::camera
