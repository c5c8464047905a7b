// avc surfacer: the avc-surfacer service. Surfaces every clusters product (PRODUCT/CLUSTERS)
// into one mesh (the paper's Algorithm 3) and publishes it on PRODUCT/MESH, with the plant's
// traits written beside the mesh when --output is given.

#include <memory>
#include <stdexcept>
#include <string>

#include "core/bus/service_runtime.h"
#include "core/stage/stage_names.h"
#include "core/stage/stage_server.h"
#include "services/surfacer/surface_step.h"
#include "services/surfacer/surfacer_node.h"
#include "services/surfacer/surfacer_options.h"
#include "tools/avc/bus_flags.h"
#include "tools/avc/commands.h"
#include "tools/avc/config_flags.h"
#include "tools/avc/run_guarded.h"
#include "tools/avc/stage_service.h"

namespace avc::cli {
namespace {

struct SurfacerArgs {
  surfacer::SurfacerNodeOptions node;
  std::string output;
  ConfigFlags config;
  bus::BusFlags bus;
};

int RunSurfacer(SurfacerArgs args) {
  surfacer::SurfacerNodeOptions options = args.node;
  const auto& table = surfacer::SurfacerOptionTable();
  options.surfacing = LoadOptions(table, args.config, options.surfacing);
  options.output_dir = args.output;
  if (const std::string problem = options.Validate(); !problem.empty()) {
    throw std::invalid_argument(problem);
  }
  bus::ServiceRuntime runtime(options.service, args.bus);
  surfacer::SurfacerNode node(runtime.bus(), runtime.loop(), runtime.heartbeat(), options);
  // A scan's surface stage (`avc scan` sends the clusters, views, masks and soil as a job).
  const auto stages =
      ServeStage(runtime, stage::kSurfaceStage, surfacer::SurfaceStageHandler(options.surfacing),
                 table.ToToml(options.surfacing));
  return runtime.Run();
}

}  // namespace

void RegisterSurfacer(CLI::App& root, int* exit_code) {
  auto args = std::make_shared<SurfacerArgs>();
  CLI::App* command = root.add_subcommand(
      "surfacer",
      "Run the avc-surfacer service. Triangulates every clusters product (PRODUCT/CLUSTERS)\n"
      "into one connected mesh (the paper's Algorithm 3: cells on each cluster's regression\n"
      "plane, boundary growth (level sets on the plant masks with --masks-from), mesh repairs\n"
      "and smoothing, refinement onto the surface fitted to\n"
      "each cluster's points, cell merging) and publishes it on\n"
      "PRODUCT/MESH as a binary PLY (per-face label = cluster id, per-vertex colours), one\n"
      "answer per clusters product (an empty mesh when nothing could be surfaced; the reason\n"
      "is logged and in the heartbeat).");
  ConfigFlags* config = &args->config;
  AddShorthand(command, config, "--spacing", "surface.spacing",
               "point spacing in m that every threshold is a multiple of (0: measured)");
  AddShorthand(command, config, "--alpha-factor", "surface.alpha_factor",
               "Phase 1 alpha in spacings");
  AddShorthand(command, config, "--stitch-factor", "surface.stitch_factor",
               "Phase 4 stitch distance in spacings between cells of different clusters");
  AddShorthand(command, config, "--own-cluster-stitch-factor", "surface.own_cluster_stitch_factor",
               "Phase 4 stitch distance in spacings between cells of one cluster");
  AddShorthand(command, config, "--stitch-link-mean-slope", "surface.stitch_link_mean_slope",
               "stitch cells of different clusters only where they continue one surface "
               "(negative: off; see BENCHMARKS.md)");
  AddShorthandSwitch(command, config, "--stitch-over-other-cells",
                     "surface.stitch_clear_of_other_cells", "false",
                     "let Phase 4's stitches pass over or under a third cell");
  AddShorthand(command, config, "--refine-subdivisions", "surface.refine_subdivisions",
               "1-to-4 subdivisions of each cell before refinement");
  AddShorthandSwitch(command, config, "--no-refine", "surface.refine", "false",
                     "keep the piecewise-flat mesh through the points");
  command
      ->add_option("--masks-from", args->node.images_dir,
                   "a reconstruction folder (cameras.json and masks/, as the builder writes "
                   "them) whose plant masks drive Phase 2's level sets, read again for every "
                   "clusters product (default: none, the band growth)")
      ->check(CLI::ExistingDirectory);
  AddShorthand(command, config, "--max-growth-factor", "surface.image_growth.max_growth_factor",
               "with --masks-from: how far a cell may grow, in spacings");
  command->add_option("--ground-z", args->node.surfacing.traits.ground_z,
                      "height of the ground in m that plant height is measured from (default: "
                      "the mesh's lowest point)");
  command->add_option("--output", args->output,
                      "also write each result to OUTPUT/<cloud id>/ as mesh.ply, traits.csv "
                      "and traits.json");
  AddConfigFlags(command, config, surfacer::SurfacerOptionTable().Reference({}));
  AddBusFlags(command, &args->bus);
  SetGuardedRun(command, exit_code, [args] { return RunSurfacer(*args); });
}

}  // namespace avc::cli
