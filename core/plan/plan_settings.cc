#include "core/plan/plan_settings.h"

#include <fmt/format.h>

#include <stdexcept>

namespace avc::plan {

const std::vector<AlgorithmSetting>& AlgorithmSettings() {
  static const std::vector<AlgorithmSetting> settings = {
      {kMaxViews, true, {"views", "most views a scan keeps (Algorithm 1's budget)", 1, 10000}},
      {kLevels, true, {"", "heights of the initial orbit", 1, 100}},
      {kViewsPerLevel, true, {"views", "views per height of the initial orbit", 1, 1000}},
      {kPruneFaceLoss,
       false,
       {"",
        "Phase 3 drops a view when at most this fraction of covered proxy faces is lost: "
        "higher keeps fewer images",
        0, 1}},
      {kKeepOutMargin, false, {"m", "the arm's keep-out around the plant proxy", 0, 1}}};
  return settings;
}

const config::OptionSpec& AlgorithmSettingSpec(std::string_view name) {
  for (const AlgorithmSetting& setting : AlgorithmSettings()) {
    if (setting.name == name) return setting.spec;
  }
  throw std::logic_error(fmt::format("{} is not one of Algorithm 1's plan settings", name));
}

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
