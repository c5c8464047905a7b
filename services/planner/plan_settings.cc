#include "services/planner/plan_settings.h"

#include <fmt/format.h>

#include <optional>
#include <stdexcept>

#include "core/kinematics/safety_envelope.h"
#include "core/plan/plan_settings.h"

namespace avc::planner {
namespace {

config::OptionTable<PlanSettings> MakeTable() {
  config::OptionTable<PlanSettings> table("planner");
  const auto spec = [](const char* name) { return plan::AlgorithmSettingSpec(name); };
  table
      .Add(
          plan::kMaxViews, [](auto& o) -> auto& { return o.planner.max_views; },
          spec(plan::kMaxViews))
      .Add(
          plan::kLevels, [](auto& o) -> auto& { return o.planner.levels; }, spec(plan::kLevels))
      .Add(
          plan::kViewsPerLevel, [](auto& o) -> auto& { return o.planner.views_per_level; },
          spec(plan::kViewsPerLevel))
      .Add(
          plan::kPruneFaceLoss,
          [](auto& o) -> auto& { return o.planner.prune_max_covered_faces_lost; },
          spec(plan::kPruneFaceLoss))
      .Add(
          plan::kKeepOutMargin, [](auto& o) -> auto& { return o.keep_out_margin; },
          spec(plan::kKeepOutMargin));
  return table;
}

double EnvelopeLength(const std::string& name, const std::string& text, double min) {
  try {
    return config::ParseReal(text, {"m", "", min, 1e6});
  } catch (const config::ConfigError& e) {
    throw config::ConfigError(fmt::format("planner: plan setting {}={}: {}", name, text, e.what()));
  }
}

}  // namespace

const config::OptionTable<PlanSettings>& PlanOptionTable() {
  static const config::OptionTable<PlanSettings> table = MakeTable();
  return table;
}

PlanSettings ParsePlanSettings(const std::vector<std::string>& assignments, PlanSettings settings) {
  std::optional<double> table_z;
  double table_clearance = kinematics::SafetyEnvelope{}.table_clearance_m;
  std::optional<kinematics::KeepOutCylinder> keep_out;
  std::vector<config::Assignment> algorithm;
  for (const std::string& text : assignments) {
    const config::Assignment assignment = config::ParseAssignment(text, "plan setting");
    const std::string& value = assignment.value;
    if (assignment.name == plan::kTableZ) {
      table_z = EnvelopeLength(assignment.name, value, -1e6);
    } else if (assignment.name == plan::kTableClearance) {
      table_clearance = EnvelopeLength(assignment.name, value, 0);
    } else if (assignment.name == plan::kKeepOut) {
      keep_out = kinematics::ParseKeepOut(value);
      if (!keep_out) {
        throw config::ConfigError(fmt::format(
            "planner: plan setting keep_out: '{}' is not five numbers (x y radius z_min z_max)",
            value));
      }
    } else {
      algorithm.push_back(assignment);
    }
  }
  PlanOptionTable().Apply(settings, algorithm);
  if (table_z || keep_out) {
    kinematics::SafetyEnvelope driver;
    driver.table_z_base_m = table_z;
    driver.table_clearance_m = table_clearance;
    driver.keep_out = keep_out;
    if (const std::string problem = driver.Validate(); !problem.empty()) {
      throw config::ConfigError("planner: the plan's safety envelope is not usable: " + problem);
    }
    settings.planner.reach.envelope = kinematics::PlanningEnvelope(driver);
  }
  return settings;
}

std::map<std::string, std::string> DescribePlanSettings(const PlanSettings& settings) {
  const ActiveVisionOptions& planner = settings.planner;
  std::map<std::string, std::string> described = {
      {plan::kMaxViews, std::to_string(planner.max_views)},
      {plan::kLevels, std::to_string(planner.levels)},
      {plan::kViewsPerLevel, std::to_string(planner.views_per_level)},
      {plan::kPruneFaceLoss, fmt::format("{}", planner.prune_max_covered_faces_lost)},
      {plan::kKeepOutMargin, fmt::format("{}", settings.keep_out_margin)}};
  return described;
}

}  // namespace avc::planner
