// avc sim: the simulated cell. `avc sim render` writes a simulated scan with its ground truth.

#include <fmt/format.h>
#include <unistd.h>

#include <cmath>
#include <iostream>
#include <memory>

#include "sim/dataset/render_dataset.h"
#include "tools/avc/commands.h"
#include "tools/avc/run_guarded.h"

namespace avc::cli {
namespace {

struct SimRenderArgs {
  std::string plant = "rosette";
  double min_elevation_deg = 15;
  double max_elevation_deg = 55;
  uint32_t cell_seed = 1;
  bool nominal_cell = false;
  std::string background = "cloth";
  sim::RenderDatasetOptions options;
};

int RunSimRender(SimRenderArgs args) {
  sim::RenderDatasetOptions& options = args.options;
  options.preset = sim::ParsePreset(args.plant);
  options.min_elevation = args.min_elevation_deg * M_PI / 180;
  options.max_elevation = args.max_elevation_deg * M_PI / 180;
  if (args.nominal_cell) {
    options.cell_seed.reset();
  } else {
    options.cell_seed = args.cell_seed;
  }
  options.render.background.kind =
      args.background == "plain" ? sim::Background::Kind::kPlain : sim::Background::Kind::kCloth;
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
  sim::RenderDatasetOptions& o = args->options;
  CLI::App* command = sim.add_subcommand(
      "render",
      "Render a simulated scan of a plant, with its ground truth.\n"
      "The plant (a preset, or any mesh file) stands on the turntable and is seen from views\n"
      "the arm can reach in a simulated (by default slightly imperfect) cell. Writes\n"
      "images/, labels/ (16-bit organ ids), depth/ (float metres), cameras.json, colmap/,\n"
      "gt_mesh.ply, cell_truth.json, views.json and scene.json into --output.\n"
      "Example: avc sim render --plant strap --views 30 --output /tmp/strap");
  command->add_option("--plant", args->plant, "preset: rosette, broadleaf, strap or bushy")
      ->capture_default_str();
  command->add_option("--seed", o.plant_seed, "plant seed (same seed, same plant)")
      ->capture_default_str();
  command->add_option("--triangles", o.plant.target_triangles, "approximate plant triangles")
      ->capture_default_str()
      ->check(CLI::Range(1000, 5'000'000));
  command->add_option("--mesh", o.mesh_file, "render this mesh (PLY, OBJ, OFF) instead of a preset")
      ->check(CLI::ExistingFile);
  command->add_option("--mesh-scale", o.placement.scale,
                      "file units to metres, e.g. 0.001 for mm (default: fit --mesh-height)");
  command->add_option("--mesh-height", o.placement.target_height, "height in metres to scale to")
      ->capture_default_str();
  command->add_flag("--y-up", o.placement.y_up, "the mesh's up axis is +y");
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
  command->add_option("--cell-seed", args->cell_seed, "seed of the perturbed cell")
      ->capture_default_str();
  command->add_flag("--nominal-cell", args->nominal_cell,
                    "a perfect cell instead of a perturbed one");
  command->add_option("--width", o.width, "image width in pixels (default 1280)");
  command->add_option("--height", o.height, "image height in pixels (default 960)");
  command
      ->add_option("--samples", o.render.samples_per_pixel_axis,
                   "anti-aliasing: N x N samples per pixel")
      ->capture_default_str()
      ->check(CLI::Range(1, 8));
  command->add_option("--background", args->background, "plain or cloth")
      ->capture_default_str()
      ->check(CLI::IsMember({"plain", "cloth"}));
  command->add_flag("--noise", o.noise, "add exposure changes and pixel noise");
  command->add_option("-o,--output", o.output, "directory to create")->required();
  SetGuardedRun(command, exit_code, [args] { return RunSimRender(*args); });
}

}  // namespace

void RegisterSim(CLI::App& root, int* exit_code) {
  CLI::App* sim = root.add_subcommand("sim", "The simulated cell (no hardware needed).");
  sim->require_subcommand(1);
  RegisterSimRender(*sim, exit_code);
}

}  // namespace avc::cli
