#include "tools/avc/planner_flags.h"

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

}  // namespace avc::cli
