#include "core/dataset/dataset_reader.h"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <sstream>
#include <stdexcept>

#include "core/camera/camera_io.h"
#include "core/dataset/exact_pose.h"
#include "core/dataset/romi_index.h"
#include "core/dataset/world_up.h"

namespace avc::dataset {
namespace fs = std::filesystem;
namespace {

std::vector<fs::path> MiddleburyParameterFiles(const fs::path& dir) {
  std::vector<fs::path> found;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.size() > 8 && name.ends_with("_par.txt")) found.push_back(entry.path());
  }
  std::sort(found.begin(), found.end());
  return found;
}

// The folder holding cameras.txt + images.txt, or empty.
fs::path ColmapModelDir(const fs::path& dir) {
  for (const fs::path& candidate : {dir, dir / "colmap", dir / "sparse", dir / "sparse" / "0"}) {
    if (fs::is_regular_file(candidate / "cameras.txt") &&
        fs::is_regular_file(candidate / "images.txt")) {
      return candidate;
    }
  }
  return {};
}

[[noreturn]] void Fail(const fs::path& file, const std::string& what) {
  throw std::runtime_error(fmt::format("{}: {}", file.string(), what));
}

std::vector<camera::NamedCamera> ReadMiddleburyParameters(const fs::path& file) {
  std::ifstream in(file);
  if (!in) Fail(file, "cannot open");
  std::string line;
  int line_number = 0;
  size_t count = 0;
  while (std::getline(in, line)) {
    ++line_number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::istringstream first(line);
    if (!(first >> count))
      Fail(file, fmt::format("line {}: expected the number of images", line_number));
    break;
  }
  std::vector<camera::NamedCamera> cameras;
  while (cameras.size() < count && std::getline(in, line)) {
    ++line_number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::istringstream fields(line);
    camera::NamedCamera named;
    double v[21];
    fields >> named.name;
    for (double& x : v) fields >> x;
    if (!fields) {
      Fail(file, fmt::format("line {}: expected a name and 21 numbers (K, R, t)", line_number));
    }
    for (double x : v) {
      if (!std::isfinite(x))
        Fail(file, fmt::format("line {}: a number is not finite", line_number));
    }
    if (std::abs(v[1]) > 1e-9 || std::abs(v[3]) > 1e-9 || std::abs(v[6]) > 1e-9 ||
        std::abs(v[7]) > 1e-9 || std::abs(v[8] - 1) > 1e-9) {
      Fail(file, fmt::format("line {}: K must be [fx 0 cx; 0 fy cy; 0 0 1]", line_number));
    }
    auto& k = named.camera.intrinsics;
    k.fx = v[0];
    k.cx = v[2];
    k.fy = v[4];
    k.cy = v[5];
    Eigen::Matrix3d r;
    r << v[9], v[10], v[11], v[12], v[13], v[14], v[15], v[16], v[17];
    const auto pose = ExactPose(r, Eigen::Vector3d(v[18], v[19], v[20]));
    if (!pose) Fail(file, fmt::format("line {}: R is not a rotation", line_number));
    named.camera.T_cam_world = *pose;
    cameras.push_back(std::move(named));
  }
  if (cameras.size() != count) {
    Fail(file, fmt::format("announces {} images but lists {}", count, cameras.size()));
  }
  return cameras;
}

cv::Mat ReadImage(const fs::path& path, int flags, const std::string& what) {
  if (!fs::is_regular_file(path)) Fail(path, what + " not found");
  cv::Mat image = cv::imread(path.string(), flags);
  if (image.empty()) Fail(path, what + " cannot be decoded");
  return image;
}

// The unit cameras.json declares ("units": "m" or "mm"), or kAuto when it declares none.
LengthUnit DeclaredScanUnit(const fs::path& cameras_json) {
  std::ifstream in(cameras_json);
  const nlohmann::json json = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (json.is_discarded() || !json.is_object() || !json.contains("units")) return LengthUnit::kAuto;
  try {
    return ParseLengthUnit(json["units"].get<std::string>());
  } catch (const std::exception& error) {
    Fail(cameras_json, fmt::format("\"units\": {}", error.what()));
  }
}

// The cameras alone, for the unit and orientation decisions. Middlebury and ROMI give no image
// size (the image's own is taken later); the optical axes these decisions use do not depend on
// it, so a size round the principal point stands in.
std::vector<camera::Camera> CamerasOf(const std::vector<camera::NamedCamera>& named) {
  std::vector<camera::Camera> cameras;
  for (const auto& entry : named) {
    camera::Camera camera = entry.camera;
    if (camera.intrinsics.width == 0) camera.intrinsics.width = 2 * camera.intrinsics.cx + 1;
    if (camera.intrinsics.height == 0) camera.intrinsics.height = 2 * camera.intrinsics.cy + 1;
    cameras.push_back(camera);
  }
  return cameras;
}

// Decides the dataset's unit and converts the cameras to metres (x_cam = R X + t: scaling the
// world scales t).
UnitDecision ConvertToMetres(std::vector<camera::NamedCamera>& named, LengthUnit requested,
                             LengthUnit declared, const std::string& declared_by,
                             const fs::path& dir) {
  const UnitDecision decision =
      DecideLengthUnit(CamerasOf(named), requested, declared, declared_by, dir.string());
  const double scale = MetresPerUnit(decision.unit);
  for (auto& entry : named) entry.camera.T_cam_world.translation() *= scale;
  return decision;
}

// Turns the world so that the cameras' up is +z, recording the turn in the set.
void TurnUpright(std::vector<camera::NamedCamera>& named, ViewSet& set) {
  const std::optional<UprightTurn> turn = FindUprightTurn(CamerasOf(named));
  if (!turn) return;
  // x_cam = R X + t with X = Q^T X': the pose becomes [R Q^T | t].
  for (auto& entry : named) {
    entry.camera.T_cam_world.linear() =
        entry.camera.T_cam_world.linear() * turn->rotation.transpose();
  }
  set.world_rotation = turn->rotation;
  set.orientation_note =
      fmt::format("the cameras' up is the file's {} axis: turned to +z", turn->from_axis);
}

fs::path MaskPath(const fs::path& masks_dir, const std::string& image_name) {
  const fs::path same = masks_dir / image_name;
  if (fs::is_regular_file(same)) return same;
  fs::path png = same;
  png.replace_extension(".png");
  if (fs::is_regular_file(png)) return png;
  return {};
}

}  // namespace

std::string DetectDatasetFormat(const fs::path& dir) {
  if (fs::is_regular_file(dir / "cameras.json")) return "scan";
  if (!ColmapModelDir(dir).empty()) return "colmap";
  if (!MiddleburyParameterFiles(dir).empty()) return "middlebury";
  if (IsRomiScan(dir)) return "romi";
  return {};
}

ViewSet ReadDataset(const fs::path& dir, const ReadOptions& options) {
  if (options.stride < 1) throw std::invalid_argument("stride must be at least 1");
  if (!fs::is_directory(dir)) Fail(dir, "not a directory");
  ViewSet set;
  set.directory = dir;
  set.format = DetectDatasetFormat(dir);
  std::vector<camera::NamedCamera> cameras;
  fs::path images_dir = dir;
  LengthUnit declared = LengthUnit::kAuto;
  std::string declared_by;
  if (set.format == "scan") {
    cameras = camera::ReadCamerasJson(dir / "cameras.json");
    images_dir = dir / "images";
    if (fs::is_regular_file(dir / "gt_mesh.ply")) set.ground_truth_mesh = dir / "gt_mesh.ply";
    declared = DeclaredScanUnit(dir / "cameras.json");
    declared_by = "cameras.json";
  } else if (set.format == "colmap") {
    const fs::path model = ColmapModelDir(dir);
    cameras = camera::ReadColmapText(model);
    if (fs::is_directory(dir / "images")) images_dir = dir / "images";
  } else if (set.format == "middlebury") {
    const auto files = MiddleburyParameterFiles(dir);
    if (files.size() > 1) {
      Fail(dir, fmt::format("holds {} *_par.txt files; keep one per directory", files.size()));
    }
    cameras = ReadMiddleburyParameters(files.front());
  } else if (set.format == "romi") {
    cameras = ReadRomiIndex(dir / "index.json");
    images_dir = dir / "undist";
    declared = LengthUnit::kMillimetre;
    declared_by = "index.json, ROMI's layout";
  } else {
    Fail(dir,
         "no cameras.json (scan directory), cameras.txt + images.txt (COLMAP text model), "
         "*_par.txt (Middlebury) or index.json (ROMI scan) found");
  }
  if (cameras.empty()) Fail(dir, "lists no images");
  const UnitDecision unit = ConvertToMetres(cameras, options.units, declared, declared_by, dir);
  set.unit = LengthUnitName(unit.unit);
  set.metres_per_unit = MetresPerUnit(unit.unit);
  set.unit_note = unit.how;
  if (options.upright) TurnUpright(cameras, set);
  const fs::path masks_dir = dir / "masks";
  for (size_t i = 0; i < cameras.size(); i += static_cast<size_t>(options.stride)) {
    View view;
    view.name = cameras[i].name;
    view.camera = cameras[i].camera;
    view.image = ReadImage(images_dir / view.name, cv::IMREAD_COLOR, "image");
    auto& k = view.camera.intrinsics;
    if (k.width == 0 && k.height == 0) {  // Middlebury and ROMI give no size: the image's own
      k.width = view.image.cols;
      k.height = view.image.rows;
    }
    if (view.image.cols != k.width || view.image.rows != k.height) {
      Fail(images_dir / view.name, fmt::format("is {}x{} but its camera is {}x{}", view.image.cols,
                                               view.image.rows, k.width, k.height));
    }
    if (const std::string problem = k.Validate(); !problem.empty()) {
      Fail(dir, fmt::format("camera of {}: {}", view.name, problem));
    }
    if (options.load_masks && fs::is_directory(masks_dir)) {
      if (const fs::path mask_file = MaskPath(masks_dir, view.name); !mask_file.empty()) {
        cv::Mat mask = ReadImage(mask_file, cv::IMREAD_GRAYSCALE, "mask");
        if (mask.size() != view.image.size()) {
          Fail(mask_file, fmt::format("is {}x{} but its image is {}x{}", mask.cols, mask.rows,
                                      view.image.cols, view.image.rows));
        }
        view.mask = mask > 0;
      }
    }
    set.views.push_back(std::move(view));
  }
  return set;
}

}  // namespace avc::dataset
