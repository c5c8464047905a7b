// avc builder: the avc-builder service. Carves the plant proxy from the scan's images as they
// arrive (PRODUCT/IMAGE + CAMERA), publishes it on PRODUCT/VOXEL_MAP, and runs multi-view stereo
// on BUILD_COMMAND RUN_MVS, publishing the points on PRODUCT/MVS_POINTS.

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/bus/service_runtime.h"
#include "core/stage/stage_names.h"
#include "services/builder/build_step.h"
#include "services/builder/builder_node.h"
#include "services/builder/builder_options.h"
#include "tools/avc/builder_flags.h"
#include "tools/avc/bus_flags.h"
#include "tools/avc/commands.h"
#include "tools/avc/config_flags.h"
#include "tools/avc/run_guarded.h"
#include "tools/avc/stage_service.h"

namespace avc::cli {
namespace {

struct BuilderArgs {
  builder::BuilderNodeOptions node;
  std::string box;
  std::string output;
  ConfigFlags config;
  bus::BusFlags bus;
};

// "xmin,ymin,zmin,xmax,ymax,zmax" in metres.
Eigen::AlignedBox3d ParseBox(const std::string& text) {
  std::vector<double> values;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t end = std::min(text.find(',', start), text.size());
    double value = 0;
    const char* first = text.data() + start;
    const char* last = text.data() + end;
    const auto [stop, error] = std::from_chars(first, last, value);
    if (error != std::errc() || stop != last || !std::isfinite(value)) {
      throw std::invalid_argument(
          fmt::format("--box: '{}' is not a finite number", std::string(first, last)));
    }
    values.push_back(value);
    start = end + 1;
  }
  if (values.size() != 6) {
    throw std::invalid_argument(fmt::format(
        "--box takes 6 numbers xmin,ymin,zmin,xmax,ymax,zmax (metres), got {}", values.size()));
  }
  const Eigen::Vector3d min(values[0], values[1], values[2]);
  const Eigen::Vector3d max(values[3], values[4], values[5]);
  if ((max.array() <= min.array()).any()) {
    throw std::invalid_argument("--box: every max must be greater than its min");
  }
  return Eigen::AlignedBox3d(min, max);
}

int RunBuilder(BuilderArgs args) {
  builder::BuilderNodeOptions options = args.node;
  const auto& table = builder::BuilderOptionTable();
  options.reconstruct = LoadOptions(table, args.config);
  if (!args.box.empty()) options.box = ParseBox(args.box);
  options.output_dir = args.output;
  if (const std::string problem = options.Validate(); !problem.empty()) {
    throw std::invalid_argument(problem);
  }
  bus::ServiceRuntime runtime(options.service, args.bus);
  builder::BuilderNode node(runtime.bus(), runtime.loop(), runtime.heartbeat(), options);
  // A scan's build stage (`avc scan` sends its images and cameras as a job).
  const auto stages =
      ServeStage(runtime, stage::kBuildStage, builder::BuildStageHandler(options.reconstruct),
                 table.ToToml(options.reconstruct));
  return runtime.Run();
}

}  // namespace

void RegisterBuilder(CLI::App& root, int* exit_code) {
  auto args = std::make_shared<BuilderArgs>();
  CLI::App* command = root.add_subcommand(
      "builder",
      "Run the avc-builder service. Pairs every image product (PRODUCT/IMAGE) with its camera\n"
      "(CAMERA), masks it and carves it into the plant proxy, which is created over an automatic\n"
      "box once --views-for-bounds views are in and published after every view on\n"
      "PRODUCT/VOXEL_MAP (.bt). BUILD_COMMAND: RESET, INCREASE_RESOLUTION, and RUN_MVS, which\n"
      "publishes multi-view stereo points on PRODUCT/MVS_POINTS.");
  command
      ->add_option("--views-for-bounds", args->node.views_for_bounds,
                   "views whose masks bound the proxy's box")
      ->capture_default_str();
  AddBuilderShorthands(command, &args->config, "--method");
  command
      ->add_option("--scan-id", args->node.scan_id, "names the products until RESET names another")
      ->capture_default_str();
  command->add_option("--output", args->output,
                      "also write the latest proxy (ppr.bt) and each MVS result (PLY) here");
  AddConfigFlags(command, &args->config,
                 builder::BuilderOptionTable().Reference(builder::ReconstructOptions{}));
  AddBusFlags(command, &args->bus);
  SetGuardedRun(command, exit_code, [args] { return RunBuilder(*args); });
}

}  // namespace avc::cli
