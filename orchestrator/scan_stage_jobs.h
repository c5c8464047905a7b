#pragma once

// The reconstruction stages of a scan as jobs for the stage services (core/stage): which
// service runs each and which files of the scan it is sent. The stages answer with their output
// files, which the scan keeps in model/.
//   build    avc-builder    cameras.json, the kept views' images/, gt_mesh.ply if any
//                           -> points.ply, ppr.bt, build.json, soil.json, images/, masks/, ...
//   cluster  avc-clusterer  model/points.ply, ppr.bt, build.json -> clusters.ply, clusters.lcm
//   surface  avc-surfacer   model/clusters.lcm, ppr.bt, soil.json, cameras.json, images/, masks/
//                           -> mesh.ply, traits.csv, traits.json, surface.json

#include <filesystem>
#include <string>
#include <vector>

namespace avc::orchestrator {

struct StageJobSpec {
  std::string service;
  std::string stage;
  std::filesystem::path folder;     // the files' root
  std::vector<std::string> inputs;  // relative to folder
};

// Throws std::runtime_error naming the file when cameras.json cannot be read.
StageJobSpec BuildJob(const std::filesystem::path& scan_dir);
StageJobSpec ClusterJob(const std::filesystem::path& model_dir);
StageJobSpec SurfaceJob(const std::filesystem::path& model_dir);

}  // namespace avc::orchestrator
