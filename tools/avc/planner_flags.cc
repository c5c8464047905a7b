#include "tools/avc/planner_flags.h"

#include <fmt/format.h>

#include "services/planner/plan_settings.h"

namespace avc::cli {

PlannerFlagOptions AddPlannerFlags(CLI::App* command, planner::ActiveVisionOptions* planner) {
  PlannerFlagOptions options;
  options.max_views =
      command->add_option("--max-views", planner->max_views, "most images the planner captures")
          ->capture_default_str()
          ->check(CLI::Range(4, 200));
  options.prune_face_loss =
      command
          ->add_option("--prune-face-loss", planner->prune_max_covered_faces_lost,
                       "fraction of the plant proxy's well-seen faces that removing redundant "
                       "views may leave under 3 views (1: the paper's rule alone; 0.01 with "
                       "--max-views 50 keeps more views and coverage, see BENCHMARKS.md nbv)")
          ->capture_default_str()
          ->check(CLI::Range(0.0, 1.0));
  return options;
}

std::map<std::string, std::string> PlanJobSettings(
    const planner::ActiveVisionOptions& planner,
    const std::optional<kinematics::SafetyEnvelope>& driver) {
  std::map<std::string, std::string> settings = planner::DescribePlanSettings({planner});
  if (!driver) return settings;
  if (driver->table_z_base_m) settings["table_z"] = fmt::format("{}", *driver->table_z_base_m);
  settings["table_clearance"] = fmt::format("{}", driver->table_clearance_m);
  if (const auto& cylinder = driver->keep_out) {
    settings["keep_out"] =
        fmt::format("{} {} {} {} {}", cylinder->centre_base.x(), cylinder->centre_base.y(),
                    cylinder->radius_m, cylinder->z_min_m, cylinder->z_max_m);
  }
  return settings;
}

}  // namespace avc::cli
