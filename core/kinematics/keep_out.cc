#include "core/kinematics/keep_out.h"

#include <fmt/format.h>

#include <cmath>
#include <sstream>

namespace avc::kinematics {

std::string KeepOutText(const KeepOutCylinder& cylinder) {
  return fmt::format("{} {} {} {} {}", cylinder.centre_base.x(), cylinder.centre_base.y(),
                     cylinder.radius_m, cylinder.z_min_m, cylinder.z_max_m);
}

std::optional<KeepOutCylinder> ParseKeepOut(const std::string& text) {
  std::istringstream numbers(text);
  double n[5];
  for (double& x : n) {
    if (!(numbers >> x)) return std::nullopt;
  }
  std::string rest;
  if (numbers >> rest) return std::nullopt;
  return KeepOutCylinder{Eigen::Vector2d(n[0], n[1]), n[2], n[3], n[4]};
}

std::string KeepOutCylinder::Validate() const {
  if (!centre_base.allFinite() || !std::isfinite(radius_m) || !std::isfinite(z_min_m) ||
      !std::isfinite(z_max_m)) {
    return "keep-out cylinder has a non-finite value";
  }
  if (!(radius_m >= 0)) return fmt::format("keep-out radius {} m is negative", radius_m);
  if (!(z_min_m <= z_max_m)) {
    return fmt::format("keep-out z range [{}, {}] m is empty", z_min_m, z_max_m);
  }
  return {};
}

double KeepOutCylinder::RadialDistance(const Eigen::Vector3d& p_base) const {
  return (p_base.head<2>() - centre_base).norm();
}

bool KeepOutCylinder::Contains(const Eigen::Vector3d& p_base) const {
  return RadialDistance(p_base) < radius_m && p_base.z() > z_min_m && p_base.z() < z_max_m;
}

}  // namespace avc::kinematics
