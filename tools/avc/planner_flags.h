#pragma once

// The planner flags avc scan and avc demo share (--max-views, --prune-face-loss), bound to the
// planner's own options so their defaults are the planner's.

#include <CLI/CLI.hpp>
#include <map>
#include <string>

#include "core/kinematics/safety_envelope.h"
#include "services/planner/active_vision.h"

namespace avc::cli {

struct PlannerFlagOptions {
  CLI::Option* max_views = nullptr;
  CLI::Option* prune_face_loss = nullptr;
};

// Adds the flags to command, writing into planner.
PlannerFlagOptions AddPlannerFlags(CLI::App* command, planner::ActiveVisionOptions* planner);

// The plan jobs' settings (services/planner/plan_settings.h) for `planner`'s counts, and the
// arm's safety envelope as avc robot enforces it (`driver`; none: the planner checks reach only).
std::map<std::string, std::string> PlanJobSettings(
    const planner::ActiveVisionOptions& planner,
    const std::optional<kinematics::SafetyEnvelope>& driver);

}  // namespace avc::cli
