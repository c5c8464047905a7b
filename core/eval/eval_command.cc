#include "core/eval/eval_command.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>

#include "core/camera/camera_io.h"
#include "core/eval/coverage.h"
#include "core/eval/eval_report_html.h"
#include "core/eval/metrics.h"
#include "core/eval/report_json.h"
#include "core/eval/report_plot.h"
#include "core/geometry/mesh_io.h"
#include "core/geometry/point_cloud_io.h"
#include "core/util/validation.h"

namespace avc::eval {
namespace {

std::string LowerExtension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

void RequireFile(const std::filesystem::path& path, const std::string& role) {
  if (path.empty()) throw std::invalid_argument(fmt::format("no {} file given", role));
  if (!std::filesystem::is_regular_file(path)) {
    throw std::invalid_argument(fmt::format("{} {}: no such file", role, path.string()));
  }
}

void WriteText(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  if (!out) throw std::runtime_error(fmt::format("{}: cannot write", path.string()));
}

void Scale(double scale, std::vector<Eigen::Vector3f>& points) {
  if (scale == 1) return;
  for (Eigen::Vector3f& p : points) p = (p.cast<double>() * scale).cast<float>();
}

geometry::Mesh ReadGroundTruth(const std::filesystem::path& path) {
  RequireFile(path, "ground truth");
  geometry::Mesh mesh;
  try {
    mesh = geometry::ReadMesh(path);
  } catch (const std::exception& e) {
    throw std::runtime_error(fmt::format("ground truth {}: {}", path.string(), e.what()));
  }
  if (mesh.num_faces() == 0) {
    throw std::invalid_argument(fmt::format(
        "ground truth {}: has no faces (the ground truth must be a mesh)", path.string()));
  }
  return mesh;
}

std::vector<camera::Camera> ReadCameras(const std::filesystem::path& path) {
  RequireFile(path, "cameras");
  std::vector<camera::Camera> cameras;
  for (const camera::NamedCamera& named : camera::ReadCamerasJson(path)) {
    ValidateCamera(named.camera,
                   fmt::format("{}: camera {} ({})", path.string(), cameras.size(), named.name));
    cameras.push_back(named.camera);
  }
  return cameras;
}

}  // namespace

std::variant<geometry::Mesh, geometry::PointCloud> ReadReconstruction(
    const std::filesystem::path& path) {
  RequireFile(path, "reconstruction");
  const std::string ext = LowerExtension(path);
  try {
    if (ext == ".xyz" || (ext == ".ply" && !geometry::PlyHasFaces(path))) {
      return geometry::ReadPointCloud(path);
    }
    if (ext == ".ply" || ext == ".obj" || ext == ".off") {
      geometry::Mesh mesh = geometry::ReadMesh(path);
      if (mesh.num_faces() > 0) return mesh;
      geometry::PointCloud cloud;
      cloud.positions = std::move(mesh.vertices);
      cloud.colors = std::move(mesh.colors);
      return cloud;
    }
  } catch (const std::exception& e) {
    throw std::runtime_error(fmt::format("reconstruction {}: {}", path.string(), e.what()));
  }
  throw std::invalid_argument(fmt::format(
      "reconstruction {}: unknown format (expected .ply, .obj, .off or .xyz)", path.string()));
}

nlohmann::json RunEvalCommand(const EvalCommandOptions& options) {
  if (!(options.scale > 0) || !std::isfinite(options.scale)) {
    throw std::invalid_argument(
        fmt::format("--scale {} must be positive and finite", options.scale));
  }
  EvalOptions eval_options;
  eval_options.thresholds = options.thresholds;
  eval_options.samples_per_m2 = options.samples_per_m2;
  eval_options.seed = options.seed;
  RequireValid(eval_options);
  CoverageOptions coverage_options;
  coverage_options.min_views = options.min_views;
  coverage_options.max_grazing_deg = options.max_grazing_deg;
  RequireValid(coverage_options);
  // Read the cameras first: a bad file should not wait for the evaluation.
  const std::vector<camera::Camera> cameras =
      options.cameras.empty() ? std::vector<camera::Camera>() : ReadCameras(options.cameras);

  geometry::Mesh gt = ReadGroundTruth(options.ground_truth);
  Scale(options.scale, gt.vertices);
  std::variant<geometry::Mesh, geometry::PointCloud> reconstruction =
      ReadReconstruction(options.reconstruction);
  EvalResult result;
  if (auto* mesh = std::get_if<geometry::Mesh>(&reconstruction)) {
    Scale(options.scale, mesh->vertices);
    result = EvaluateMesh(gt, *mesh, eval_options);
  } else {
    auto& cloud = std::get<geometry::PointCloud>(reconstruction);
    Scale(options.scale, cloud.positions);
    result = EvaluatePointCloud(gt, cloud, eval_options);
  }

  nlohmann::json report = ToJson(result);
  report["inputs"] = {
      {"ground_truth", options.ground_truth.string()},
      {"reconstruction", options.reconstruction.string()},
      {"scale", options.scale},
      {"cameras", options.cameras.empty() ? nlohmann::json(nullptr)
                                          : nlohmann::json(options.cameras.string())}};
  if (!options.cameras.empty()) {
    const CoverageModel model(gt, result.gt_samples, coverage_options);
    report["coverage"] = ToJson(model.Evaluate(cameras));
  }

  if (!options.json_output.empty()) WriteText(options.json_output, report.dump(2) + "\n");
  if (!options.plot_output.empty() || !options.html_output.empty()) {
    const std::vector<uint8_t> png = RenderErrorPlotPng(result);
    if (!options.plot_output.empty()) {
      WriteText(options.plot_output, std::string(png.begin(), png.end()));
    }
    if (!options.html_output.empty()) WriteText(options.html_output, RenderHtml(report, png));
  }
  return report;
}

}  // namespace avc::eval
