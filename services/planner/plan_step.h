#pragma once

// avc-planner's side of a plan job (plan_exchange.h): the job's calibration.yaml, settings
// (plan_settings.h) and answered views in, plan.json out. Sessions (plan_session.h) live from
// job to job per scan, so the planner plans each scan once; a job that does not continue its
// scan's session (a resumed scan, a restarted planner, other settings or calibration) starts a
// new one, which replays the answered views.

#include "core/stage/stage_server.h"
#include "services/planner/plan_settings.h"

namespace avc::planner {

inline constexpr char kCalibrationFile[] = "calibration.yaml";

// The handler for a StageServer of stage "plan", planning with `settings` (the planner's
// configuration) changed by each job's. It keeps the sessions of the last few scans.
stage::StageHandler PlanStageHandler(const PlanSettings& settings = {});

}  // namespace avc::planner
