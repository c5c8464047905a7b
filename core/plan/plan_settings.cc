#include "core/plan/plan_settings.h"

#include <fmt/format.h>

namespace avc::plan {

void AddEnvelopeSettings(const kinematics::SafetyEnvelope& driver,
                         std::map<std::string, std::string>* settings) {
  // fmt's shortest form reads back to the same double.
  if (driver.table_z_base_m) (*settings)[kTableZ] = fmt::format("{}", *driver.table_z_base_m);
  (*settings)[kTableClearance] = fmt::format("{}", driver.table_clearance_m);
  if (const auto& cylinder = driver.keep_out) {
    (*settings)[kKeepOut] = kinematics::KeepOutText(*cylinder);
  }
}

}  // namespace avc::plan
