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
  table
      .Add(plan::kMaxViews, [](auto& o) -> auto& { return o.planner.max_views; },
           {"views", "most views a scan keeps (Algorithm 1's budget)", 1, 10000})
      .Add(plan::kLevels, [](auto& o) -> auto& { return o.planner.levels; },
           {"", "heights of the initial orbit", 1, 100})
      .Add(plan::kViewsPerLevel, [](auto& o) -> auto& { return o.planner.views_per_level; },
           {"views", "views per height of the initial orbit", 1, 1000})
      .Add(plan::kPruneFaceLoss,
           [](auto& o) -> auto& { return o.planner.prune_max_covered_faces_lost; },
           {"",
            "Phase 3 drops a view when at most this fraction of covered proxy faces is lost: "
            "higher keeps fewer images",
            0, 1})
      .Add(plan::kKeepOutMargin, [](auto& o) -> auto& { return o.keep_out_margin; },
           {"m", "the arm's keep-out around the plant proxy", 0, 1});
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
