// avc clusterer: the avc-clusterer service. Merges every MVS points product (PRODUCT/MVS_POINTS)
// into the latest plant proxy (PRODUCT/VOXEL_MAP), clusters it (Algorithm 2) and publishes the
// result on PRODUCT/CLUSTERS.

#include <memory>
#include <stdexcept>
#include <string>

#include "core/bus/service_runtime.h"
#include "core/stage/stage_names.h"
#include "core/stage/stage_server.h"
#include "services/clusterer/cluster_step.h"
#include "services/clusterer/clusterer_node.h"
#include "services/clusterer/clusterer_options.h"
#include "tools/avc/bus_flags.h"
#include "tools/avc/cluster_cli.h"
#include "tools/avc/commands.h"
#include "tools/avc/run_guarded.h"
#include "tools/avc/stage_service.h"

namespace avc::cli {
namespace {

struct ClustererArgs {
  clusterer::ClustererNodeOptions node;
  ClusterFlags cluster;
  std::string output;
  bus::BusFlags bus;
};

int RunClusterer(ClustererArgs args) {
  clusterer::ClustererNodeOptions options = args.node;
  options.clustering = args.cluster.Options();
  options.output_dir = args.output;
  if (const std::string problem = options.Validate(); !problem.empty()) {
    throw std::invalid_argument(problem);
  }
  bus::ServiceRuntime runtime(options.service, args.bus);
  clusterer::ClustererNode node(runtime.bus(), runtime.loop(), runtime.heartbeat(), options);
  // A scan's cluster stage (`avc scan` sends the build's points and proxy as a job).
  const auto stages =
      ServeStage(runtime, stage::kClusterStage, clusterer::ClusterStageHandler(options.clustering),
                 clusterer::ClustererOptionTable().ToToml(options.clustering));
  return runtime.Run();
}

}  // namespace

void RegisterClusterer(CLI::App& root, int* exit_code) {
  auto args = std::make_shared<ClustererArgs>();
  CLI::App* command = root.add_subcommand(
      "clusterer",
      "Run the avc-clusterer service. Keeps the latest plant proxy (PRODUCT/VOXEL_MAP); merges\n"
      "every MVS points product (PRODUCT/MVS_POINTS) into its voxels (one averaged point per\n"
      "voxel holding more than 3), clusters the merged points into surface patches (the\n"
      "paper's Algorithm 2) and publishes them on PRODUCT/CLUSTERS, one answer per cloud (with\n"
      "the reason when nothing could be clustered).");
  command
      ->add_option("--max-waiting", args->node.max_waiting,
                   "MVS clouds held while no proxy has arrived")
      ->capture_default_str();
  AddClusterFlags(command, &args->cluster);
  command->add_option("--output", args->output,
                      "also write each result here as clusters_<cloud id>.ply");
  AddBusFlags(command, &args->bus);
  SetGuardedRun(command, exit_code, [args] { return RunClusterer(*args); });
}

}  // namespace avc::cli
