#include "orchestrator/scan_stage_jobs.h"

#include <algorithm>

#include "core/camera/camera_io.h"
#include "core/stage/stage_names.h"

namespace avc::orchestrator {
namespace {

namespace fs = std::filesystem;

// The files directly in root/folder, as "folder/name", sorted.
std::vector<std::string> FilesIn(const fs::path& root, const std::string& folder) {
  std::vector<std::string> files;
  if (!fs::is_directory(root / folder)) return files;
  for (const fs::directory_entry& entry : fs::directory_iterator(root / folder)) {
    if (entry.is_regular_file()) files.push_back(folder + "/" + entry.path().filename().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

StageJobSpec BuildJob(const fs::path& scan_dir) {
  StageJobSpec job{stage::kBuildService, stage::kBuildStage, scan_dir, {"cameras.json"}};
  for (const camera::NamedCamera& camera : camera::ReadCamerasJson(scan_dir / "cameras.json")) {
    job.inputs.push_back("images/" + camera.name);
  }
  // A simulated scan's truth: build.json scores the points against it.
  if (fs::exists(scan_dir / "gt_mesh.ply")) job.inputs.push_back("gt_mesh.ply");
  return job;
}

StageJobSpec ClusterJob(const fs::path& model_dir) {
  return {stage::kClusterService,
          stage::kClusterStage,
          model_dir,
          {"points.ply", "ppr.bt", "build.json"}};
}

StageJobSpec SurfaceJob(const fs::path& model_dir) {
  StageJobSpec job{stage::kSurfaceService,
                   stage::kSurfaceStage,
                   model_dir,
                   {stage::kClustersMessageFile, "ppr.bt", "cameras.json"}};
  if (fs::exists(model_dir / "soil.json")) job.inputs.push_back("soil.json");
  for (const char* folder : {"images", "masks"}) {
    for (std::string& file : FilesIn(model_dir, folder)) job.inputs.push_back(std::move(file));
  }
  return job;
}

}  // namespace avc::orchestrator
