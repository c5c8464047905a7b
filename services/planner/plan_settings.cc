#include "services/planner/plan_settings.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "core/kinematics/safety_envelope.h"
#include "core/plan/plan_settings.h"

namespace avc::planner {
namespace {

template <typename T>
T Parse(const std::string& name, const std::string& text, T min, T max) {
  T value{};
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (error != std::errc() || stop != end) {
    throw std::invalid_argument(fmt::format("plan setting {}: '{}' is not a number", name, text));
  }
  if (!(value >= min && value <= max)) {
    throw std::invalid_argument(
        fmt::format("plan setting {}: {} is outside [{}, {}]", name, value, min, max));
  }
  return value;
}

// Shortest text that reads back to the same double.
std::string Text(double value) { return fmt::format("{}", value); }

}  // namespace

PlanSettings ParsePlanSettings(const std::vector<std::string>& assignments) {
  PlanSettings settings;
  ActiveVisionOptions& planner = settings.planner;
  std::optional<double> table_z;
  double table_clearance = kinematics::SafetyEnvelope{}.table_clearance_m;
  std::optional<kinematics::KeepOutCylinder> keep_out;
  for (const std::string& assignment : assignments) {
    const size_t equals = assignment.find('=');
    if (equals == std::string::npos) {
      throw std::invalid_argument(fmt::format("plan setting '{}' is not name=value", assignment));
    }
    const std::string name = assignment.substr(0, equals);
    const std::string value = assignment.substr(equals + 1);
    constexpr double kHuge = 1e6;
    if (name == plan::kMaxViews) {
      planner.max_views = Parse(name, value, 1, 10000);
    } else if (name == plan::kLevels) {
      planner.levels = Parse(name, value, 1, 100);
    } else if (name == plan::kViewsPerLevel) {
      planner.views_per_level = Parse(name, value, 1, 1000);
    } else if (name == plan::kPruneFaceLoss) {
      planner.prune_max_covered_faces_lost = Parse(name, value, 0.0, 1.0);
    } else if (name == plan::kTableZ) {
      table_z = Parse(name, value, -kHuge, kHuge);
    } else if (name == plan::kTableClearance) {
      table_clearance = Parse(name, value, 0.0, kHuge);
    } else if (name == plan::kKeepOut) {
      keep_out = plan::ParseKeepOut(value);
      if (!keep_out) {
        throw std::invalid_argument(fmt::format(
            "plan setting keep_out: '{}' is not five numbers (x y radius z_min z_max)", value));
      }
    } else if (name == plan::kKeepOutMargin) {
      settings.keep_out_margin = Parse(name, value, 0.0, 1.0);
    } else {
      throw std::invalid_argument(
          fmt::format("unknown plan setting '{}' (known: max_views, levels, views_per_level, "
                      "prune_face_loss, table_z, table_clearance, keep_out, keep_out_margin)",
                      name));
    }
  }
  if (table_z || keep_out) {
    kinematics::SafetyEnvelope driver;
    driver.table_z_base_m = table_z;
    driver.table_clearance_m = table_clearance;
    driver.keep_out = keep_out;
    if (const std::string problem = driver.Validate(); !problem.empty()) {
      throw std::invalid_argument("plan settings: the safety envelope is not usable: " + problem);
    }
    planner.reach.envelope = kinematics::PlanningEnvelope(driver);
  }
  return settings;
}

std::map<std::string, std::string> DescribePlanSettings(const PlanSettings& settings) {
  const ActiveVisionOptions& planner = settings.planner;
  std::map<std::string, std::string> described = {
      {plan::kMaxViews, std::to_string(planner.max_views)},
      {plan::kLevels, std::to_string(planner.levels)},
      {plan::kViewsPerLevel, std::to_string(planner.views_per_level)},
      {plan::kPruneFaceLoss, Text(planner.prune_max_covered_faces_lost)},
      {plan::kKeepOutMargin, Text(settings.keep_out_margin)}};
  return described;
}

}  // namespace avc::planner
