#pragma once

// The settings a plan job may carry ("name=value"), as avc scan sends them to avc-planner:
//   max_views, levels, views_per_level, prune_face_loss   Algorithm 1's counts (active_vision.h)
//   table_z, table_clearance, keep_out                    the arm's fixed safety envelope, as
//                                                         avc robot enforces it (keep_out: "x y
//                                                         radius z_min z_max", base frame, m)
//   keep_out_margin                                       plant proxy to arm keep-out, m
// Unset ones keep the planner's defaults; no envelope setting: the planner checks reach only.

#include <map>
#include <string>
#include <vector>

#include "core/config/option_table.h"
#include "services/planner/active_vision.h"

namespace avc::planner {

struct PlanSettings {
  ActiveVisionOptions planner;
  double keep_out_margin = 0.02;
};

// avc-planner's own options (--config, --set, its published configuration): the names above
// but the envelope, which is the cell's and comes with each job.
const config::OptionTable<PlanSettings>& PlanOptionTable();

// `settings` (the planner's configuration) changed by a job's `assignments`. Throws
// config::ConfigError naming the setting for an unknown name, a malformed value or one out of
// range.
PlanSettings ParsePlanSettings(const std::vector<std::string>& assignments,
                               PlanSettings settings = {});

// Algorithm 1's counts and the keep-out margin in force, by name, as text that ParsePlanSettings
// reads back to the same values (for the scan's report).
std::map<std::string, std::string> DescribePlanSettings(const PlanSettings& settings);

}  // namespace avc::planner
