#include "sim/dataset/render_dataset.h"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>

#include "core/camera/camera_io.h"
#include "core/geometry/mesh_io.h"
#include "core/util/validation.h"
#include "sim/cell/cell_truth_json.h"
#include "sim/cell/noise.h"
#include "sim/cell/perturbation.h"
#include "sim/cell/view_selection.h"
#include "sim/render/renderer.h"

namespace avc::sim {
namespace {

namespace fs = std::filesystem;

struct View {
  std::string name;
  kinematics::JointVector joints;
  double turntable_angle = 0;
  double elevation = 0;
  double distance = 0;  // camera centre to plant centre, metres
  camera::Camera camera;
};

void PrepareOutput(const fs::path& output) {
  std::error_code error;
  if (fs::exists(output, error) && !fs::is_empty(output, error)) {
    throw std::runtime_error(output.string() + " exists and is not empty; choose a new directory");
  }
  for (const char* sub : {"images", "labels", "depth"}) fs::create_directories(output / sub);
}

}  // namespace

std::string RenderDatasetOptions::Validate() const {
  const RenderDatasetOptions& options = *this;
  if (options.views < 1) return "views must be at least 1";
  if (options.rings < 1 || options.rings > options.views) {
    return fmt::format("rings must be between 1 and the number of views ({})", options.views);
  }
  if (!(options.min_elevation >= -1.2 && options.max_elevation <= 1.5 &&
        options.min_elevation <= options.max_elevation)) {
    return "elevations must satisfy -69 deg <= min <= max <= 86 deg";
  }
  if (!(options.distance >= 0) || !std::isfinite(options.distance)) {
    return "distance must be a non-negative number of metres";
  }
  if ((options.width == 0) != (options.height == 0) || options.width < 0 || options.height < 0) {
    return "give both width and height (positive), or neither";
  }
  if (options.output.empty()) return "no output directory given";
  return {};
}

Scene MakeScene(const RenderDatasetOptions& options) {
  if (options.chessboard) return ChessboardScene(*options.chessboard);
  if (!options.mesh_file.empty()) {
    return SceneFromMesh(geometry::ReadMesh(options.mesh_file), options.placement);
  }
  return GeneratePlant(options.preset, options.plant_seed, options.plant);
}

CellTruth MakeCell(const RenderDatasetOptions& options) {
  CellTruth cell = options.cell_seed ? PerturbedCell(*options.cell_seed) : NominalCell();
  if (options.width > 0) {
    // Another sensor size with the same lens: scale the pixel grid.
    camera::Intrinsics& k = cell.intrinsics;
    const double sx = static_cast<double>(options.width) / k.width;
    const double sy = static_cast<double>(options.height) / k.height;
    k.fx *= sx, k.cx = (k.cx + 0.5) * sx - 0.5;
    k.fy *= sy, k.cy = (k.cy + 0.5) * sy - 0.5;
    k.width = options.width, k.height = options.height;
  }
  return cell;
}

namespace {

// The distance at which the plant, seen from `elevation`, spans the image: its turning radius
// across, its height (foreshortened) plus its footprint (seen from above) up and down, plus a
// margin for the near side, which images larger.
double FitDistance(const camera::Intrinsics& k, double turning_radius, double height,
                   double elevation) {
  const double across = turning_radius / (0.5 * k.width / k.fx);
  const double vertical =
      (0.5 * height * std::cos(elevation) + turning_radius * std::sin(elevation)) /
      (0.5 * k.height / k.fy);
  return std::max(across, vertical) + 0.3 * turning_radius;
}

// Joints for a camera `distance` from the target at `elevation`; with `shrink`, the nearest
// reachable distance below it (in 1 cm steps, down to 0.25 m) when the arm cannot reach that far.
std::optional<kinematics::JointVector> ReachView(const CellTruth& cell,
                                                 const Eigen::Vector3d& target, double elevation,
                                                 double azimuth, double* distance, bool shrink,
                                                 const kinematics::JointVector& current) {
  for (double d = *distance; d >= 0.25; d -= 0.01) {
    const Eigen::Vector3d eye = ViewpointOnSphere(target, d, elevation, azimuth);
    if (auto joints = JointsLookingAt(cell, eye, target, current)) {
      *distance = d;
      return joints;
    }
    if (!shrink) break;
  }
  return std::nullopt;
}

std::vector<View> PlanViews(const RenderDatasetOptions& options, const CellTruth& cell,
                            const Scene& scene) {
  Eigen::Vector3f min, max;
  geometry::Bounds(scene.mesh, &min, &max);
  double turning_radius = 0;
  for (const Eigen::Vector3f& v : scene.mesh.vertices) {
    turning_radius = std::max(turning_radius, static_cast<double>(v.head<2>().norm()));
  }
  const double height = max.z() - min.z();
  const Eigen::Vector3d centre_world(0, 0, 0.5 * (min.z() + max.z()));
  const double azimuth = RobotAzimuth(cell);
  kinematics::JointVector current = StartJoints(cell);
  std::vector<View> views;
  for (int ring = 0; ring < options.rings; ++ring) {
    const int in_ring = options.views / options.rings + (ring < options.views % options.rings);
    const double elevation =
        options.rings == 1
            ? 0.5 * (options.min_elevation + options.max_elevation)
            : options.min_elevation +
                  (options.max_elevation - options.min_elevation) * ring / (options.rings - 1);
    const bool automatic = options.distance == 0;
    const double wanted = automatic
                              ? FitDistance(cell.intrinsics, turning_radius, height, elevation)
                              : options.distance;
    for (int j = 0; j < in_ring; ++j) {
      View view;
      view.name = fmt::format("view_{:04d}.png", views.size());
      // Rings are offset by a fraction of a step so no two rings share a turntable angle.
      view.turntable_angle = 2 * M_PI * (j + static_cast<double>(ring) / options.rings) / in_ring;
      view.elevation = elevation;
      view.distance = wanted;
      const Eigen::Vector3d target = TableFromWorld(cell, view.turntable_angle) * centre_world;
      const auto joints =
          ReachView(cell, target, elevation, azimuth, &view.distance, automatic, current);
      if (!joints) {
        throw std::runtime_error(fmt::format(
            "the arm cannot reach view {} (elevation {:.1f} deg, {:.3f} m from the plant centre); "
            "try a smaller --max-elevation or another --distance",
            views.size(), elevation * 180 / M_PI, wanted));
      }
      view.joints = current = *joints;
      view.camera = CameraAt(cell, view.joints, view.turntable_angle);
      views.push_back(std::move(view));
    }
  }
  return views;
}

void WriteImage(const fs::path& path, const cv::Mat& image) {
  if (!cv::imwrite(path.string(), image)) throw std::runtime_error("cannot write " + path.string());
}

void WriteJson(const fs::path& path, const nlohmann::ordered_json& json) {
  std::ofstream out(path, std::ios::trunc);
  out << json.dump(1) << "\n";
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

nlohmann::ordered_json SceneJson(const RenderDatasetOptions& options, const Scene& scene) {
  std::map<int32_t, geometry::Mesh> organs;
  for (size_t f = 0; f < scene.mesh.faces.size(); ++f) {
    geometry::Mesh& organ = organs[scene.mesh.face_labels[f]];
    if (organ.vertices.empty()) organ.vertices = scene.mesh.vertices;
    organ.faces.push_back(scene.mesh.faces[f]);
  }
  nlohmann::ordered_json areas = nlohmann::ordered_json::array();
  for (const auto& [label, organ] : organs) {
    areas.push_back({{"label", label},
                     {"organ", geometry::labels::Name(label)},
                     {"triangles", organ.faces.size()},
                     {"area_m2", geometry::SurfaceArea(organ)}});
  }
  nlohmann::ordered_json json;
  json["name"] = scene.name;
  if (options.mesh_file.empty()) {
    json["preset"] = std::string(PresetName(options.preset));
    json["plant_seed"] = options.plant_seed;
  } else {
    json["mesh_file"] = options.mesh_file.string();
  }
  json["vertices"] = scene.mesh.vertices.size();
  json["triangles"] = scene.mesh.faces.size();
  json["organs"] = areas;
  return json;
}

}  // namespace

RenderDatasetSummary RenderDataset(const RenderDatasetOptions& options,
                                   const ProgressCallback& progress) {
  RequireValid(options);
  if (const std::string problem = ValidateRenderOptions(options.render); !problem.empty()) {
    throw std::invalid_argument(problem);
  }
  const Scene scene = MakeScene(options);
  const CellTruth cell = MakeCell(options);
  const std::vector<View> views = PlanViews(options, cell, scene);
  PrepareOutput(options.output);

  RenderDatasetSummary summary;
  summary.triangles = scene.mesh.faces.size();
  auto wrote = [&](const std::string& file) { summary.files.push_back(file); };
  std::vector<camera::NamedCamera> cameras;
  nlohmann::ordered_json views_json = nlohmann::ordered_json::array();
  for (size_t i = 0; i < views.size(); ++i) {
    const View& view = views[i];
    if (progress) progress(static_cast<int>(i), static_cast<int>(views.size()), view.name);
    const auto start = std::chrono::steady_clock::now();
    RenderResult result = Render(scene, view.camera, options.render);
    summary.seconds_rendering +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (options.noise) {
      ApplyImageNoise(result.color, ImageNoise{},
                      (uint64_t{options.cell_seed.value_or(0)} << 32) | i);
    }
    const std::string stem = fs::path(view.name).stem().string();
    WriteImage(options.output / "images" / view.name, result.color);
    cv::Mat labels16;
    result.labels.convertTo(labels16, CV_16U);
    WriteImage(options.output / "labels" / (stem + ".png"), labels16);
    WriteImage(options.output / "depth" / (stem + ".tiff"), result.depth);
    wrote("images/" + view.name);
    wrote("labels/" + stem + ".png");
    wrote("depth/" + stem + ".tiff");
    cameras.push_back({view.name, view.camera});
    views_json.push_back(
        {{"name", view.name},
         {"joints_rad", std::vector<double>(view.joints.data(), view.joints.data() + 6)},
         {"turntable_angle_rad", view.turntable_angle},
         {"elevation_rad", view.elevation},
         {"distance_m", view.distance}});
  }
  if (progress) progress(static_cast<int>(views.size()), static_cast<int>(views.size()), "files");
  camera::WriteCamerasJson(options.output / "cameras.json", cameras);
  camera::WriteColmapText(options.output / "colmap", cameras);
  geometry::WriteMeshPly(options.output / "gt_mesh.ply", scene.mesh);
  SaveCellTruth(cell, options.output / "cell_truth.json");
  WriteJson(options.output / "views.json", {{"views", views_json}});
  WriteJson(options.output / "scene.json", SceneJson(options, scene));
  for (const char* file :
       {"cameras.json", "colmap/cameras.txt", "colmap/images.txt", "colmap/points3D.txt",
        "gt_mesh.ply", "cell_truth.json", "views.json", "scene.json"}) {
    wrote(file);
  }
  summary.views = static_cast<int>(views.size());
  return summary;
}

}  // namespace avc::sim
