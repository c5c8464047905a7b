#include "tools/avc/planner_flags.h"

#include <fmt/format.h>

#include "orchestrator/scan_planner_settings.h"

namespace avc::cli {

void AddPlannerFlags(CLI::App* command, PlannerFlags* flags, bool views_per_height) {
  command
      ->add_option("--max-views", flags->max_views,
                   "most images the planner captures (default: the planner's, 40)")
      ->check(CLI::Range(4, 200));
  command
      ->add_option("--prune-face-loss", flags->prune_face_loss,
                   "fraction of the plant proxy's well-seen faces that removing redundant views "
                   "may leave under 3 views (default: the planner's, 1: the paper's rule alone; "
                   "0.01 with --max-views 50 keeps more views and coverage, see BENCHMARKS.md "
                   "nbv)")
      ->check(CLI::Range(0.0, 1.0));
  if (views_per_height) {
    command
        ->add_option("--views-per-height", flags->views_per_height,
                     "orbit views per height (default: the planner's, 10)")
        ->check(CLI::Range(3, 36));
  }
}

std::map<std::string, std::string> PlanJobSettings(
    const PlannerFlags& flags, const std::optional<kinematics::SafetyEnvelope>& driver) {
  std::map<std::string, std::string> settings;
  if (flags.max_views) settings[orchestrator::kMaxViewsSetting] = std::to_string(*flags.max_views);
  if (flags.prune_face_loss) {
    settings[orchestrator::kPruneFaceLossSetting] = fmt::format("{}", *flags.prune_face_loss);
  }
  if (flags.views_per_height) {
    settings[orchestrator::kViewsPerLevelSetting] = std::to_string(*flags.views_per_height);
  }
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
