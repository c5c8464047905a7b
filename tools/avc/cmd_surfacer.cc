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
#include "tools/avc/bus_flags.h"
#include "tools/avc/commands.h"
#include "tools/avc/run_guarded.h"

namespace avc::cli {
namespace {

struct SurfacerArgs {
  surfacer::SurfacerNodeOptions node;
  std::string output;
  bus::BusFlags bus;
};

int RunSurfacer(SurfacerArgs args) {
  surfacer::SurfacerNodeOptions options = args.node;
  options.output_dir = args.output;
  if (const std::string problem = options.Validate(); !problem.empty()) {
    throw std::invalid_argument(problem);
  }
  bus::ServiceRuntime runtime(options.service, args.bus);
  surfacer::SurfacerNode node(runtime.bus(), runtime.loop(), runtime.heartbeat(), options);
  // A scan's surface stage (`avc scan` sends the clusters, views, masks and soil as a job).
  stage::StageServer stages(runtime.bus(), runtime.loop(), options.service, stage::kSurfaceStage,
                            surfacer::SurfaceStageHandler());
  return runtime.Run();
}

}  // namespace

void RegisterSurfacer(CLI::App& root, int* exit_code) {
  auto args = std::make_shared<SurfacerArgs>();
  surface::SurfaceOptions& surface = args->node.surfacing.surface;
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
  command
      ->add_option("--spacing", surface.spacing,
                   "point spacing in m that every threshold is a multiple of (0: measured, the "
                   "median nearest-neighbour distance)")
      ->capture_default_str();
  command->add_option("--alpha-factor", surface.alpha_factor, "Phase 1 alpha in spacings")
      ->capture_default_str();
  command
      ->add_option("--stitch-factor", surface.stitch_factor,
                   "Phase 4 stitch distance in spacings between cells of different clusters")
      ->capture_default_str();
  command
      ->add_option("--own-cluster-stitch-factor", surface.own_cluster_stitch_factor,
                   "Phase 4 stitch distance in spacings between cells of one cluster (0: the "
                   "--stitch-factor)")
      ->capture_default_str();
  command
      ->add_option("--stitch-link-mean-slope", surface.stitch_link_mean_slope,
                   "stitch cells of different clusters only where they continue one surface: "
                   "largest offset along the bisector of the normals per unit length (negative: "
                   "off; 0.1 with --own-cluster-stitch-factor 5.25 joins a rosette's leaves "
                   "better, see BENCHMARKS.md)")
      ->capture_default_str();
  command->add_flag(
      "--stitch-over-other-cells",
      [args](int64_t) { args->node.surfacing.surface.stitch_clear_of_other_cells = false; },
      "let Phase 4's stitches pass over or under a third cell (refused by default: at a "
      "rosette's centre they join two leaves across a third)");
  command
      ->add_option("--refine-subdivisions", surface.refine_subdivisions,
                   "1-to-4 subdivisions of each cell before its vertices are moved onto the "
                   "surface fitted to its points (0: same face count as the triangulation)")
      ->capture_default_str()
      ->check(CLI::Range(0, 3));
  command->add_flag(
      "--no-refine", [args](int64_t) { args->node.surfacing.surface.refine = false; },
      "keep the piecewise-flat mesh through the points (no fitted-surface "
      "refinement)");
  command
      ->add_option("--masks-from", args->node.images_dir,
                   "a reconstruction folder (cameras.json and masks/, as the builder writes "
                   "them) whose plant masks drive Phase 2's level sets, read again for every "
                   "clusters product (default: none, the band growth)")
      ->check(CLI::ExistingDirectory);
  command
      ->add_option("--max-growth-factor", surface.image_growth.max_growth_factor,
                   "with --masks-from: how far a cell may grow, in spacings")
      ->capture_default_str();
  command->add_option("--ground-z", args->node.surfacing.traits.ground_z,
                      "height of the ground in m that plant height is measured from (default: "
                      "the mesh's lowest point)");
  command->add_option("--output", args->output,
                      "also write each result to OUTPUT/<cloud id>/ as mesh.ply, traits.csv "
                      "and traits.json");
  AddBusFlags(command, &args->bus);
  SetGuardedRun(command, exit_code, [args] { return RunSurfacer(*args); });
}

}  // namespace avc::cli
