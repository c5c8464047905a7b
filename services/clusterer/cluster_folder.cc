#include "services/clusterer/cluster_folder.h"

#include <fmt/format.h>

#include <nlohmann/json.hpp>
#include <stdexcept>

#include "core/mvs/mvs_points_io.h"
#include "core/ppr/octree_voxels.h"
#include "core/util/file_io.h"

namespace avc::clusterer {
namespace {

namespace fs = std::filesystem;

// The exact voxel size from build.json beside the proxy (the .bt keeps 6 digits), else 0 with
// the reason in `note`.
double VoxelSizeFromReport(const fs::path& folder, std::string* note) {
  const fs::path report = folder / "build.json";
  if (!fs::exists(report)) return 0;
  try {
    const nlohmann::json json = nlohmann::json::parse(ReadFile(report));
    return json.at("proxy").at("voxel_size_m").get<double>();
  } catch (const nlohmann::json::exception& error) {
    *note = fmt::format("{}: no proxy voxel size ({}); using the tree's", report.string(),
                        error.what());
    return 0;
  }
}

}  // namespace

messages::ClustersContent ClusterFolderFiles(const fs::path& points_file,
                                             const fs::path& proxy_file,
                                             const ClustererOptions& options,
                                             FolderInputs* inputs) {
  FolderInputs read;
  read.points_file = points_file;
  read.proxy_file = proxy_file;
  const mvs::MvsPoints points = mvs::ReadMvsPointsPly(points_file);
  const mvs::MvsBounds proxy = ppr::OccupiedVoxelsFromBinary(
      ReadFile(proxy_file), VoxelSizeFromReport(proxy_file.parent_path(), &read.note),
      proxy_file.string());
  read.points = points.size();
  read.occupied_voxels = proxy.occupied_centres.size();
  read.voxel_size = proxy.voxel_size;
  if (inputs) *inputs = read;
  return MergeAndCluster(points, proxy, options, points_file.stem().string(),
                         proxy_file.stem().string());
}

}  // namespace avc::clusterer
