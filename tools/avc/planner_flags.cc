#include "tools/avc/planner_flags.h"

#include <fmt/format.h>

#include "core/plan/plan_settings.h"

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
  if (flags.max_views) settings[plan::kMaxViews] = std::to_string(*flags.max_views);
  if (flags.prune_face_loss) {
    settings[plan::kPruneFaceLoss] = fmt::format("{}", *flags.prune_face_loss);
  }
  if (flags.views_per_height) {
    settings[plan::kViewsPerLevel] = std::to_string(*flags.views_per_height);
  }
  if (driver) plan::AddEnvelopeSettings(*driver, &settings);
  return settings;
}

}  // namespace avc::cli
