#pragma once

// The planner flags avc scan and avc demo share (--max-views, --prune-face-loss, and avc scan's
// --views-per-height). Each one given becomes a plan job setting for avc-planner
// (services/planner/plan_settings.h); the others keep the planner's own defaults, which it
// reports with its first answer and the scan records. The commands link none of the planner's
// code (a configure-time check).

#include <CLI/CLI.hpp>
#include <map>
#include <optional>
#include <string>

#include "core/kinematics/safety_envelope.h"

namespace avc::cli {

struct PlannerFlags {
  std::optional<int> max_views;
  std::optional<double> prune_face_loss;
  std::optional<int> views_per_height;
};

// Adds --max-views and --prune-face-loss, and --views-per-height when asked.
void AddPlannerFlags(CLI::App* command, PlannerFlags* flags, bool views_per_height = false);

// The plan jobs' settings: the flags given, and the arm's safety envelope as avc robot enforces
// it (`driver`; none: the planner checks reach only).
std::map<std::string, std::string> PlanJobSettings(
    const PlannerFlags& flags, const std::optional<kinematics::SafetyEnvelope>& driver);

}  // namespace avc::cli
