#pragma once

// The planner flags avc scan and avc demo share (--max-views, --prune-face-loss), bound to the
// planner's own options so their defaults are the planner's.

#include <CLI/CLI.hpp>

#include "services/planner/active_vision.h"

namespace avc::cli {

struct PlannerFlagOptions {
  CLI::Option* max_views = nullptr;
  CLI::Option* prune_face_loss = nullptr;
};

// Adds the flags to command, writing into planner.
PlannerFlagOptions AddPlannerFlags(CLI::App* command, planner::ActiveVisionOptions* planner);

}  // namespace avc::cli
