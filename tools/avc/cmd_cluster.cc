// avc cluster: the clusterer offline on a reconstruction folder (what `avc reconstruct` or the
// builder node wrote): points.ply merged into ppr.bt's voxels and clustered, written as
// clusters.ply beside them.

#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>

#include "services/clusterer/cluster_folder.h"
#include "services/clusterer/clusters_ply.h"
#include "services/clusterer/merge_and_cluster.h"
#include "tools/avc/cluster_cli.h"
#include "tools/avc/commands.h"
#include "tools/avc/run_guarded.h"

namespace avc::cli {
namespace {

namespace fs = std::filesystem;

struct ClusterArgs {
  std::string folder;
  std::string points;
  std::string proxy;
  std::string output;
  ClusterFlags cluster;
  bool overwrite = false;
};

int RunCluster(const ClusterArgs& args) {
  const fs::path folder = args.folder;
  const fs::path points_file = args.points.empty() ? folder / "points.ply" : fs::path(args.points);
  const fs::path proxy_file = args.proxy.empty() ? folder / "ppr.bt" : fs::path(args.proxy);
  const fs::path output = args.output.empty() ? folder : fs::path(args.output);
  const fs::path clusters_file = output / "clusters.ply";
  if (fs::exists(clusters_file) && !args.overwrite) {
    throw std::runtime_error(clusters_file.string() + " exists; --overwrite replaces it");
  }
  const auto start = std::chrono::steady_clock::now();
  clusterer::FolderInputs inputs;
  const messages::ClustersContent content =
      clusterer::ClusterFolderFiles(points_file, proxy_file, args.cluster.Options(), &inputs);
  if (!inputs.note.empty()) std::cerr << inputs.note << "\n";
  std::cerr << fmt::format("{}: {} MVS points; {}: {} occupied voxels of {:.2f} mm\n",
                           points_file.string(), inputs.points, proxy_file.string(),
                           inputs.occupied_voxels, inputs.voxel_size * 1e3);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << DescribeClusters(content) << fmt::format(" ({:.2f} s)\n", seconds);
  if (!content.problem.empty()) return 1;
  fs::create_directories(output);
  clusterer::WriteClustersPly(clusters_file, content);
  std::cout << "wrote " << clusters_file.string() << "\n";
  return 0;
}

}  // namespace

void RegisterCluster(CLI::App& root, int* exit_code) {
  auto args = std::make_shared<ClusterArgs>();
  CLI::App* command = root.add_subcommand(
      "cluster",
      "Merge and cluster a reconstruction offline (paper §3): the MVS points (points.ply) are\n"
      "merged into the plant proxy's voxels (ppr.bt; one averaged point per voxel holding more\n"
      "than 3) and clustered into surface patches (Algorithm 2), written as clusters.ply with\n"
      "a `cluster` property per point (-1: outlier) and its voxel index.\n"
      "\n"
      "Example: avc cluster rosette-result");
  command->add_option("folder", args->folder, "reconstruction folder (points.ply, ppr.bt)")
      ->required()
      ->check(CLI::ExistingDirectory);
  command->add_option("--points", args->points, "MVS points PLY (default: FOLDER/points.ply)")
      ->check(CLI::ExistingFile);
  command->add_option("--proxy", args->proxy, "plant proxy .bt (default: FOLDER/ppr.bt)")
      ->check(CLI::ExistingFile);
  command->add_option("--output", args->output, "where clusters.ply goes (default: FOLDER)");
  AddClusterFlags(command, &args->cluster);
  command->add_flag("--overwrite", args->overwrite, "replace an existing clusters.ply");
  SetGuardedRun(command, exit_code, [args] { return RunCluster(*args); });
}

}  // namespace avc::cli
