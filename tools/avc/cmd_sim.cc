// avc sim: the simulated cell. `avc sim render` writes a simulated scan with its ground truth;
// `avc sim cell` (cmd_sim_cell.cc) runs the live cell the drivers connect to.

#include <fmt/format.h>
#include <unistd.h>

#include <cmath>
#include <iostream>
#include <memory>

#include "sim/dataset/render_dataset.h"
#include "tools/avc/commands.h"
#include "tools/avc/run_guarded.h"
#include "tools/avc/sim_scene_flags.h"

namespace avc::cli {
namespace {

struct SimRenderArgs {
  SimSceneArgs scene;
  double min_elevation_deg = 15;
  double max_elevation_deg = 55;
};

int RunSimRender(SimRenderArgs args) {
  ResolveSimScene(args.scene);
  sim::RenderDatasetOptions& options = args.scene.options;
  options.min_elevation = args.min_elevation_deg * M_PI / 180;
  options.max_elevation = args.max_elevation_deg * M_PI / 180;
  const sim::RenderDatasetSummary summary =
      sim::RenderDataset(options, [](int done, int total, const std::string& what) {
        // One line rewritten in place on a terminal, a line per step in a log.
        const char* end = isatty(STDERR_FILENO) ? "\r" : "\n";
        if (done < total)
          std::cerr << fmt::format("rendering {}/{} {}{}", done + 1, total, what, end);
        if (done == total) std::cerr << "writing cameras, ground truth and metadata   \n";
      });
  std::cout << fmt::format(
      "wrote {} views of {} triangles to {} ({:.2f} s rendering, {:.0f} ms per view)\n",
      summary.views, summary.triangles, options.output.string(), summary.seconds_rendering,
      1000 * summary.seconds_rendering / summary.views);
  return 0;
}

void RegisterSimRender(CLI::App& sim, int* exit_code) {
  auto args = std::make_shared<SimRenderArgs>();
  sim::RenderDatasetOptions& o = args->scene.options;
  CLI::App* command = sim.add_subcommand(
      "render",
      "Render a simulated scan of a plant, with its ground truth.\n"
      "The plant (a preset, or any mesh file) stands on the turntable and is seen from views\n"
      "the arm can reach in a simulated (by default slightly imperfect) cell. Writes\n"
      "images/, labels/ (16-bit organ ids), depth/ (float metres), cameras.json, colmap/,\n"
      "gt_mesh.ply, cell_truth.json, views.json and scene.json into --output.\n"
      "Example: avc sim render --plant strap --views 30 --output /tmp/strap");
  AddSimSceneFlags(*command, args->scene);
  command->add_option("--views", o.views, "number of views")
      ->capture_default_str()
      ->check(CLI::Range(1, 10'000));
  command->add_option("--rings", o.rings, "elevation rings the views are spread over")
      ->capture_default_str();
  command->add_option("--min-elevation", args->min_elevation_deg, "lowest ring, degrees")
      ->capture_default_str();
  command->add_option("--max-elevation", args->max_elevation_deg, "highest ring, degrees")
      ->capture_default_str();
  command->add_option("--distance", o.distance,
                      "camera distance from the plant centre, metres (default: fit the plant)");
  command->add_option("-o,--output", o.output, "directory to create")->required();
  SetGuardedRun(command, exit_code, [args] { return RunSimRender(*args); });
}

}  // namespace

void RegisterSim(CLI::App& root, int* exit_code) {
  CLI::App* sim = root.add_subcommand("sim", "The simulated cell (no hardware needed).");
  sim->require_subcommand(1);
  RegisterSimRender(*sim, exit_code);
  RegisterSimCell(*sim, exit_code);
}

}  // namespace avc::cli
