#include "orchestrator/scan_planner_settings.h"

#include <fmt/format.h>

#include <stdexcept>

namespace avc::orchestrator {
namespace {

constexpr char kMaxViews[] = "max_views";
constexpr char kLevels[] = "levels";
constexpr char kViewsPerLevel[] = "views_per_level";
constexpr char kPruneFaceLoss[] = "prune_face_loss";

[[noreturn]] void Fail(const char* key, const std::string& what) {
  throw std::runtime_error(fmt::format(
      "scan.json options.{} {}: the scan cannot be resumed with the planner it started with", key,
      what));
}

void RestoreInteger(const nlohmann::json& options, const char* key, int min, int* value) {
  const auto it = options.find(key);
  if (it == options.end()) return;
  if (!it->is_number_integer()) Fail(key, "must be an integer, got " + it->dump());
  const int64_t recorded = it->get<int64_t>();
  if (recorded < min || recorded > 10000) {
    Fail(key, fmt::format("must be in [{}, 10000], got {}", min, recorded));
  }
  *value = static_cast<int>(recorded);
}

}  // namespace

void RecordPlannerSettings(const planner::ActiveVisionOptions& planner, nlohmann::json* options) {
  (*options)[kMaxViews] = planner.max_views;
  (*options)[kLevels] = planner.levels;
  (*options)[kViewsPerLevel] = planner.views_per_level;
  (*options)[kPruneFaceLoss] = planner.prune_max_covered_faces_lost;
}

void RestorePlannerSettings(const nlohmann::json& options, planner::ActiveVisionOptions* planner) {
  if (!options.is_object()) throw std::runtime_error("scan.json options must be an object");
  RestoreInteger(options, kMaxViews, 1, &planner->max_views);
  RestoreInteger(options, kLevels, 1, &planner->levels);
  RestoreInteger(options, kViewsPerLevel, 1, &planner->views_per_level);
  if (const auto it = options.find(kPruneFaceLoss); it != options.end()) {
    if (!it->is_number()) Fail(kPruneFaceLoss, "must be a number, got " + it->dump());
    const double recorded = it->get<double>();
    if (!(recorded >= 0.0 && recorded <= 1.0)) {
      Fail(kPruneFaceLoss, fmt::format("must be in [0, 1], got {}", recorded));
    }
    planner->prune_max_covered_faces_lost = recorded;
  }
}

std::string DescribePlannerChanges(const planner::ActiveVisionOptions& recorded,
                                   const planner::ActiveVisionOptions& given) {
  std::string changes;
  auto compare = [&changes](const char* key, auto was, auto now) {
    if (was == now) return;
    changes += fmt::format("{}{} {} (given {})", changes.empty() ? "" : ", ", key, was, now);
  };
  compare(kMaxViews, recorded.max_views, given.max_views);
  compare(kLevels, recorded.levels, given.levels);
  compare(kViewsPerLevel, recorded.views_per_level, given.views_per_level);
  compare(kPruneFaceLoss, recorded.prune_max_covered_faces_lost,
          given.prune_max_covered_faces_lost);
  return changes;
}

}  // namespace avc::orchestrator
