#pragma once

// What `avc eval` does, as a function the tests call directly: read a ground-truth mesh and a
// reconstruction (mesh or point cloud), evaluate, optionally score coverage by a set of cameras,
// and write the JSON / HTML / PNG reports.

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <variant>
#include <vector>

#include "core/geometry/mesh.h"
#include "core/geometry/point_cloud.h"

namespace avc::eval {

struct EvalCommandOptions {
  std::filesystem::path ground_truth;    // mesh: .ply, .obj, .off
  std::filesystem::path reconstruction;  // mesh (.ply with faces, .obj, .off) or cloud (.ply, .xyz)
  std::vector<double> thresholds = {0.001, 0.002, 0.005, 0.01};  // metres
  double samples_per_m2 = 1e6;
  uint64_t seed = 1;
  double scale = 1;  // multiplies both files' coordinates into metres (0.001 for mm files)
  std::filesystem::path cameras;  // optional: cameras.json (core/camera/camera_io.h), metres
  int min_views = 3;
  double max_grazing_deg = 75;
  std::filesystem::path json_output;  // each optional
  std::filesystem::path html_output;
  std::filesystem::path plot_output;
};

// Runs everything and returns the report (also written to the requested files). Throws
// std::exception with a message naming the file or option at fault.
nlohmann::json RunEvalCommand(const EvalCommandOptions& options);

// A reconstruction file: a .ply whose header declares faces, an .obj or .off with faces → mesh;
// a vertex-only .ply or .obj/.off, or an .xyz → point cloud. Errors name the file.
std::variant<geometry::Mesh, geometry::PointCloud> ReadReconstruction(
    const std::filesystem::path& path);

}  // namespace avc::eval
