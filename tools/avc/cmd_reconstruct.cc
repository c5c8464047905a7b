// avc reconstruct: the reconstruction half of a scan on images with known cameras (a scan
// directory, a COLMAP text model or a Middlebury set): masks, plant proxy, multi-view stereo,
// merging, clustering and surfacing, written with a scan directory's file names.

#include <fmt/format.h>
#include <unistd.h>

#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "core/dataset/dataset_reader.h"
#include "core/util/file_io.h"
#include "services/builder/build_report.h"
#include "services/builder/builder_options.h"
#include "services/builder/reconstruction.h"
#include "services/builder/reconstruction_output.h"
#include "services/clusterer/cluster_step.h"
#include "services/clusterer/clusterer_options.h"
#include "services/surfacer/surface_step.h"
#include "services/surfacer/surfacer_options.h"
#include "tools/avc/builder_flags.h"
#include "tools/avc/cluster_cli.h"
#include "tools/avc/commands.h"
#include "tools/avc/config_flags.h"
#include "tools/avc/run_guarded.h"

namespace avc::cli {
namespace {

struct ReconstructArgs {
  std::string dataset;
  std::string output;
  int stride = 1;
  std::string units = "auto";
  bool no_evaluation = false;
  bool overwrite = false;
  bool json = false;
  ConfigFlags config;
};

// The options of the three stages this command runs, as avc-builder, avc-clusterer and
// avc-surfacer take them.
struct PipelineOptions {
  builder::ReconstructOptions build;
  clusterer::ClustererOptions cluster;
  surfacer::SurfacerOptions surface;
};

// --config files, then the shorthand flags, then --set, each sent to the stage whose table has
// the name (their sections do not overlap), so a scan folder's config/*.toml reproduce its
// stages offline.
PipelineOptions LoadPipelineOptions(const ReconstructArgs& args) {
  const std::vector<config::Assignment> all = args.config.Assignments();
  const auto& build_table = builder::BuilderOptionTable();
  const auto& cluster_table = clusterer::ClustererOptionTable();
  const auto& surface_table = surfacer::SurfacerOptionTable();
  std::vector<config::Assignment> build, cluster, surface;
  for (const config::Assignment& assignment : all) {
    if (build_table.Has(assignment.name)) {
      build.push_back(assignment);
    } else if (cluster_table.Has(assignment.name)) {
      cluster.push_back(assignment);
    } else if (surface_table.Has(assignment.name)) {
      surface.push_back(assignment);
    } else {
      throw config::ConfigError(fmt::format(
          "{} {}={}: no option of the builder, clusterer or surfacer has that name (--help "
          "lists them)",
          assignment.where, assignment.name, assignment.value));
    }
  }
  PipelineOptions options;
  build_table.Apply(options.build, build);
  cluster_table.Apply(options.cluster, cluster);
  surface_table.Apply(options.surface, surface);
  return options;
}

void ShowProgress(const std::string& stage, size_t done, size_t total) {
  const bool terminal = isatty(STDERR_FILENO);
  if (!terminal && done != total) return;  // logs get one line per finished stage
  std::cerr << fmt::format("{:<24} {}/{}", stage, done, total) << (terminal ? "\x1b[K\r" : "\n")
            << std::flush;
}

struct BuiltModel {
  size_t files = 0;
  bool has_merged_points = false;
  std::string report_json;
};

// Reads the dataset, builds and writes the model into `output`. The images, masks and proxy are
// released on return, before clustering and surfacing read what they need from the files (they
// would otherwise hold 0.5 GB more at the peak on a 72-view real scan).
BuiltModel BuildModel(const ReconstructArgs& args, const builder::ReconstructOptions& options,
                      const std::filesystem::path& output) {
  dataset::ViewSet set = dataset::ReadDataset(
      args.dataset, {.stride = args.stride, .units = dataset::ParseLengthUnit(args.units)});
  std::cerr << fmt::format("{}: {} views ({}), lengths in {}; results in metres\n", args.dataset,
                           set.views.size(), set.format, set.unit_note);
  if (!set.orientation_note.empty()) {
    std::cerr << args.dataset << ": " << set.orientation_note << "\n";
  }
  const builder::Reconstruction reconstruction = builder::Reconstruct(set, options, ShowProgress);
  if (isatty(STDERR_FILENO)) std::cerr << "\x1b[K";
  const builder::BuildReport report = builder::MakeBuildReport(
      reconstruction, options.method,
      args.no_evaluation ? std::filesystem::path() : set.ground_truth_mesh, set.FileToWorld());
  const auto files =
      builder::WriteReconstruction(output, set, reconstruction, report, args.overwrite);
  std::cout << builder::BuildReportToText(report);
  return {files.size(), reconstruction.merged.size() > 0,
          builder::BuildReportToJson(report).dump()};
}

int RunReconstruct(const ReconstructArgs& args) {
  const PipelineOptions pipeline = LoadPipelineOptions(args);
  const std::filesystem::path output = builder::ChooseOutputDirectory(args.dataset, args.output);
  const BuiltModel model = BuildModel(args, pipeline.build, output);
  size_t written = model.files;
  if (model.has_merged_points) {
    // Clustering (paper §3.2) and surfacing (§4) on the files just written, with the code
    // avc-clusterer and avc-surfacer run for a scan: the same files give the same bytes offline
    // and over the bus. Phase 2 grows the cells where the views' plant masks see leaf.
    try {
      const messages::ClustersContent clusters =
          clusterer::ClusterModel(output, output, pipeline.cluster);
      std::cout << DescribeClusters(clusters) << "\n";
      written += 2;  // clusters.ply, clusters.lcm
      surfacer::SurfaceModel(output, output, pipeline.surface);
      written += 4;  // mesh.ply, traits.csv, traits.json, surface.json
      const nlohmann::json surface = nlohmann::json::parse(ReadFile(output / "surface.json"));
      const nlohmann::json traits = nlohmann::json::parse(ReadFile(output / "traits.json"));
      std::cout << fmt::format(
          "surface: {} faces in {} pieces, {:.1f} cm^2; plant height {:.1f} mm, width {:.1f} mm\n",
          surface.at("faces").get<int64_t>(), surface.at("components").get<int64_t>(),
          1e4 * traits.at("total_area_m2").get<double>(), 1e3 * traits.at("height_m").get<double>(),
          1e3 * traits.at("width_m").get<double>());
    } catch (const std::runtime_error& error) {
      std::cout << "no surface: " << error.what() << "\n";
    }
  }
  std::cout << fmt::format("wrote {} files to {}\n", written, output.string());
  if (args.json) std::cout << model.report_json << "\n";
  return 0;
}

}  // namespace

void RegisterReconstruct(CLI::App& root, int* exit_code) {
  auto args = std::make_shared<ReconstructArgs>();
  CLI::App* command = root.add_subcommand(
      "reconstruct",
      "Reconstruct a plant from images with known cameras: plant masks (automatic unless\n"
      "masks/<image name> are given), the plant proxy (tolerant octree carving, ppr.bt) and\n"
      "multi-view stereo points (points.ply, with confidence and the images that see each\n"
      "point), merged into the proxy's voxels (merged.ply), clustered into surface patches\n"
      "(clusters.ply) and surfaced (mesh.ply; plant traits in traits.csv and traits.json).\n"
      "Datasets: a scan directory (cameras.json + images/), a COLMAP text model (cameras.txt +\n"
      "images.txt, in the folder or in sparse/ or colmap/), a Middlebury set (*_par.txt) or a\n"
      "ROMI scan (index.json + undist/, millimetres). Lengths are converted to metres.\n"
      "A simulated scan's ground truth (gt_mesh.ply) is used to report accuracy.\n"
      "\n"
      "Example: avc reconstruct --dataset scans/rosette --output rosette-result");
  command->add_option("--dataset", args->dataset, "folder with the images and cameras")
      ->required()
      ->check(CLI::ExistingDirectory);
  command->add_option("--output", args->output,
                      "folder for the results (default: <dataset>-reconstruction here)");
  AddBuilderShorthands(command, &args->config, "--mvs");
  AddShorthand(command, &args->config, "--masks", "masks.method",
               "plant masks: auto, excess_green or background_distance");
  command->add_option("--stride", args->stride, "use every Nth image")->capture_default_str();
  command
      ->add_option("--units", args->units,
                   "the dataset's length unit: m, mm, or auto (what the dataset declares, else "
                   "told from the cameras' distances); results are always in metres")
      ->check(CLI::IsMember({"auto", "m", "mm"}))
      ->capture_default_str();
  AddConfigFlags(command, &args->config, "");
  command->footer(
      "--config and --set take the options of avc-builder, avc-clusterer and avc-surfacer by\n"
      "name (`avc builder --help`, `avc clusterer --help`, `avc surfacer --help` list them):\n"
      "  avc reconstruct --dataset DIR --config SCAN/config/avc-builder.toml \\\n"
      "      --config SCAN/config/avc-clusterer.toml --config SCAN/config/avc-surfacer.toml\n"
      "reconstructs with a scan's configuration.");
  command->add_flag("--no-evaluation", args->no_evaluation, "skip the comparison with gt_mesh.ply");
  command->add_flag("--overwrite", args->overwrite, "replace results already in --output");
  command->add_flag("--json", args->json, "print the run's report as JSON last");
  SetGuardedRun(command, exit_code, [args] { return RunReconstruct(*args); });
}

}  // namespace avc::cli
