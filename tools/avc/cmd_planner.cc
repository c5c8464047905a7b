// avc planner: the avc-planner service. Plans a scan's views (the paper's Algorithm 1) as plan
// jobs from `avc scan`: each job carries the views planned so far and their plant masks, each
// answer the next view to capture, until the final plan (views kept, and why each was chosen).

#include <memory>
#include <string>

#include "core/bus/service_runtime.h"
#include "core/stage/stage_names.h"
#include "core/stage/stage_server.h"
#include "services/planner/plan_step.h"
#include "tools/avc/bus_flags.h"
#include "tools/avc/commands.h"
#include "tools/avc/config_flags.h"
#include "tools/avc/run_guarded.h"
#include "tools/avc/stage_service.h"

namespace avc::cli {
namespace {

struct PlannerArgs {
  std::string service = stage::kPlanService;
  ConfigFlags config;
  bus::BusFlags bus;
};

int RunPlanner(const PlannerArgs& args) {
  const auto& table = planner::PlanOptionTable();
  const planner::PlanSettings settings = LoadOptions(table, args.config);
  bus::ServiceRuntime runtime(args.service, args.bus);
  const auto plans = ServeStage(runtime, stage::kPlanStage, planner::PlanStageHandler(settings),
                                table.ToToml(settings));
  // Jobs queue while one is planned, so the planner takes them whenever it runs.
  runtime.heartbeat().Set(bus::ServiceState::kReady, "taking plan jobs");
  return runtime.Run();
}

}  // namespace

void RegisterPlanner(CLI::App& root, int* exit_code) {
  auto args = std::make_shared<PlannerArgs>();
  CLI::App* command = root.add_subcommand(
      "planner",
      "Run the avc-planner service: the scan's next-best-view planner (the paper's Algorithm\n"
      "1: framing, the initial orbit at three heights, next-best views for the plant proxy's\n"
      "failing patches, redundant-view removal). `avc scan` sends it plan jobs on\n"
      "PRODUCT/STAGE_JOB (the cell's calibration, the planner settings, every view planned so\n"
      "far with its plant mask) and it answers each with the next view to capture, or the\n"
      "final plan. It plans each scan once from job to job; a resumed scan or a restarted\n"
      "planner replays the answered views (the planner is deterministic).");
  command->add_option("--service", args->service, "service name on the bus")->capture_default_str();
  AddConfigFlags(command, &args->config,
                 planner::PlanOptionTable().Reference(planner::PlanSettings{}));
  AddBusFlags(command, &args->bus);
  SetGuardedRun(command, exit_code, [args] { return RunPlanner(*args); });
}

}  // namespace avc::cli
