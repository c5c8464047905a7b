#include "core/kinematics/keep_out.h"

#include <fmt/format.h>

#include <cmath>

namespace avc::kinematics {

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
