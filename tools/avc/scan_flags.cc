#include "tools/avc/scan_flags.h"

#include "orchestrator/scan_options.h"

namespace avc::cli {

void AddScanOptionFlags(CLI::App* command, ConfigFlags* config) {
  AddShorthand(command, config, "--max-views", "planner.max_views",
               "most images the planner keeps (default: the planner's, 40)");
  AddShorthand(command, config, "--prune-face-loss", "planner.prune_face_loss",
               "fraction of the proxy's well-seen faces that dropping redundant views may leave "
               "under 3 views (default: the planner's, 1: the paper's rule alone; 0.01 with "
               "--max-views 50 keeps more views and coverage, see BENCHMARKS.md nbv)");
  AddShorthand(command, config, "--views-per-height", "planner.views_per_level",
               "orbit views per height (default: the planner's, 10)");
  AddScaledShorthand(command, config, "--ready-timeout", "scan.ready_timeout", 1e3,
                     "seconds to wait for the services a step needs (default 30)");
  AddConfigFlags(command, config,
                 orchestrator::ScanOptionTable().Reference(orchestrator::ScanOptions{}));
}

}  // namespace avc::cli
