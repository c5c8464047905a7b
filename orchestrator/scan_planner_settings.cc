#include "orchestrator/scan_planner_settings.h"

#include <fmt/format.h>

#include <stdexcept>

namespace avc::orchestrator {
namespace {

[[noreturn]] void Fail(const char* key, const std::string& what) {
  throw std::runtime_error(fmt::format(
      "scan.json options.{} {}: the scan cannot be resumed with the planner it started with", key,
      what));
}

// Far above any planner count the command line allows (200 views), far below int's range.
constexpr int64_t kLargestRecordedCount = 10000;

void RestoreInteger(const nlohmann::json& options, const char* key, int min, int* value) {
  const auto it = options.find(key);
  if (it == options.end()) return;
  if (!it->is_number_integer()) Fail(key, "must be an integer, got " + it->dump());
  const int64_t recorded = it->get<int64_t>();
  if (recorded < min || recorded > kLargestRecordedCount) {
    Fail(key, fmt::format("must be in [{}, {}], got {}", min, kLargestRecordedCount, recorded));
  }
  *value = static_cast<int>(recorded);
}

}  // namespace

void RecordPlannerSettings(const planner::ActiveVisionOptions& planner, nlohmann::json* options) {
  (*options)[kMaxViewsSetting] = planner.max_views;
  (*options)[kLevelsSetting] = planner.levels;
  (*options)[kViewsPerLevelSetting] = planner.views_per_level;
  (*options)[kPruneFaceLossSetting] = planner.prune_max_covered_faces_lost;
}

void RestorePlannerSettings(const nlohmann::json& options, planner::ActiveVisionOptions* planner) {
  if (!options.is_object()) throw std::runtime_error("scan.json options must be an object");
  RestoreInteger(options, kMaxViewsSetting, 1, &planner->max_views);
  RestoreInteger(options, kLevelsSetting, 1, &planner->levels);
  RestoreInteger(options, kViewsPerLevelSetting, 1, &planner->views_per_level);
  if (const auto it = options.find(kPruneFaceLossSetting); it != options.end()) {
    if (!it->is_number()) Fail(kPruneFaceLossSetting, "must be a number, got " + it->dump());
    const double recorded = it->get<double>();
    if (!(recorded >= 0.0 && recorded <= 1.0)) {
      Fail(kPruneFaceLossSetting, fmt::format("must be in [0, 1], got {}", recorded));
    }
    planner->prune_max_covered_faces_lost = recorded;
  }
}

std::string DescribePlannerChanges(const planner::ActiveVisionOptions& recorded,
                                   const planner::ActiveVisionOptions& given,
                                   const std::set<std::string>& keys) {
  std::string changes;
  auto compare = [&changes, &keys](const char* key, auto was, auto now) {
    if (was == now || !keys.contains(key)) return;
    changes += fmt::format("{}{} {} (given {})", changes.empty() ? "" : ", ", key, was, now);
  };
  compare(kMaxViewsSetting, recorded.max_views, given.max_views);
  compare(kLevelsSetting, recorded.levels, given.levels);
  compare(kViewsPerLevelSetting, recorded.views_per_level, given.views_per_level);
  compare(kPruneFaceLossSetting, recorded.prune_max_covered_faces_lost,
          given.prune_max_covered_faces_lost);
  return changes;
}

}  // namespace avc::orchestrator
