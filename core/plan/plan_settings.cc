#include "core/plan/plan_settings.h"

#include <fmt/format.h>

#include <sstream>

namespace avc::plan {

void AddEnvelopeSettings(const kinematics::SafetyEnvelope& driver,
                         std::map<std::string, std::string>* settings) {
  // fmt's shortest form reads back to the same double.
  if (driver.table_z_base_m) (*settings)[kTableZ] = fmt::format("{}", *driver.table_z_base_m);
  (*settings)[kTableClearance] = fmt::format("{}", driver.table_clearance_m);
  if (const auto& cylinder = driver.keep_out) {
    (*settings)[kKeepOut] =
        fmt::format("{} {} {} {} {}", cylinder->centre_base.x(), cylinder->centre_base.y(),
                    cylinder->radius_m, cylinder->z_min_m, cylinder->z_max_m);
  }
}

std::optional<kinematics::KeepOutCylinder> ParseKeepOut(const std::string& text) {
  std::istringstream numbers(text);
  double n[5];
  for (double& x : n) {
    if (!(numbers >> x)) return std::nullopt;
  }
  std::string rest;
  if (numbers >> rest) return std::nullopt;
  return kinematics::KeepOutCylinder{Eigen::Vector2d(n[0], n[1]), n[2], n[3], n[4]};
}

}  // namespace avc::plan
