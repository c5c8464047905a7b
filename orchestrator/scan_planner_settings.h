#pragma once

// The planner settings a scan started with, kept in scan.json's "options". A resumed scan runs
// the planner again over its own record and must ask for the same views, so it takes these
// settings from the record; a resume whose command line asks for other ones is refused.

#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "services/planner/active_vision.h"

namespace avc::orchestrator {

// Writes the recorded settings into options (keys max_views, levels, views_per_level,
// prune_face_loss).
void RecordPlannerSettings(const planner::ActiveVisionOptions& planner, nlohmann::json* options);

// Sets planner's recorded settings from a scan's "options". A key a scan from an older version
// lacks keeps the value that version used (the default). Throws std::runtime_error naming the
// key when a recorded value has the wrong type or is out of range: scan.json was edited or
// damaged, and a guess would plan other views than those on disk.
void RestorePlannerSettings(const nlohmann::json& options, planner::ActiveVisionOptions* planner);

// The keys in scan.json's "options".
inline constexpr char kMaxViewsSetting[] = "max_views";
inline constexpr char kLevelsSetting[] = "levels";
inline constexpr char kViewsPerLevelSetting[] = "views_per_level";
inline constexpr char kPruneFaceLossSetting[] = "prune_face_loss";

// Of the settings named in keys, those given changes from recorded, as "max_views 14 (given 50),
// ..."; empty when none changes.
std::string DescribePlannerChanges(const planner::ActiveVisionOptions& recorded,
                                   const planner::ActiveVisionOptions& given,
                                   const std::set<std::string>& keys);

}  // namespace avc::orchestrator
