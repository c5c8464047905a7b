#include "orchestrator/scan_planner_settings.h"

#include <fmt/format.h>

#include <stdexcept>

#include "core/plan/plan_settings.h"

namespace avc::orchestrator {
namespace {

constexpr char kSettingsKey[] = "planner_settings";

[[noreturn]] void Fail(const std::string& key, const std::string& what) {
  throw std::runtime_error(fmt::format(
      "scan.json options.{} {}: the scan cannot be resumed with the planner it started with", key,
      what));
}

}  // namespace

void RecordPlannerSettings(const PlannerSettings& settings, nlohmann::json* options) {
  (*options)[kSettingsKey] = settings;
}

PlannerSettings RecordedPlannerSettings(const nlohmann::json& options) {
  if (!options.is_object()) throw std::runtime_error("scan.json options must be an object");
  PlannerSettings recorded;
  if (const auto it = options.find(kSettingsKey); it != options.end()) {
    if (!it->is_object()) Fail(kSettingsKey, "must be an object of strings");
    for (const auto& [key, value] : it->items()) {
      if (!value.is_string()) {
        Fail(std::string(kSettingsKey) + "." + key, "must be a string, got " + value.dump());
      }
      recorded[key] = value.get<std::string>();
    }
    return recorded;
  }
  // Older scans kept Algorithm 1's counts as numbers beside the other options.
  for (const char* key :
       {plan::kMaxViews, plan::kLevels, plan::kViewsPerLevel, plan::kPruneFaceLoss}) {
    const auto it = options.find(key);
    if (it == options.end()) continue;
    if (!it->is_number()) Fail(key, "must be a number, got " + it->dump());
    recorded[key] = it->is_number_integer() ? std::to_string(it->get<int64_t>())
                                            : fmt::format("{}", it->get<double>());
  }
  return recorded;
}

std::string DescribePlannerChanges(const PlannerSettings& recorded, const PlannerSettings& given,
                                   const std::set<std::string>& keys) {
  std::string changes;
  for (const std::string& key : keys) {
    const auto was = recorded.find(key);
    const auto now = given.find(key);
    if (was == recorded.end() || now == given.end() || was->second == now->second) continue;
    changes += fmt::format("{}{} {} (given {})", changes.empty() ? "" : ", ", key, was->second,
                           now->second);
  }
  return changes;
}

std::vector<std::string> PlannerAssignments(const PlannerSettings& settings) {
  std::vector<std::string> assignments;
  for (const auto& [key, value] : settings) assignments.push_back(key + "=" + value);
  return assignments;
}

}  // namespace avc::orchestrator
