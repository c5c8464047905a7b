#pragma once

// The planner settings a scan started with ("name=value" for avc-planner's plan jobs, see
// services/planner/plan_settings.h), kept in scan.json's "options.planner_settings". A resumed
// scan plans again over its own record and must ask for the same views, so it plans with these
// settings; a resume whose command line asks for other ones is refused.

#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

namespace avc::orchestrator {

using PlannerSettings = std::map<std::string, std::string>;

// Writes settings into options["planner_settings"].
void RecordPlannerSettings(const PlannerSettings& settings, nlohmann::json* options);

// The settings a scan recorded: options["planner_settings"], or for a scan from an older AVC the
// counts it kept beside the other options (max_views, levels, views_per_level,
// prune_face_loss). Throws std::runtime_error naming the key when a value is not a string (or,
// in an older scan, a number): scan.json was edited or damaged, and a guess would plan other
// views than those on disk.
PlannerSettings RecordedPlannerSettings(const nlohmann::json& options);

// Of the settings named in keys, those given changes from recorded, as "max_views 14 (given
// 50), ..."; empty when none changes. A key the scan did not record is no change.
std::string DescribePlannerChanges(const PlannerSettings& recorded, const PlannerSettings& given,
                                   const std::set<std::string>& keys);

// The settings as a plan job carries them: "name=value", sorted by name.
std::vector<std::string> PlannerAssignments(const PlannerSettings& settings);

}  // namespace avc::orchestrator
