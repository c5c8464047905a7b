#include "report/report_inputs.h"

#include <fmt/format.h>

#include <stdexcept>

#include "core/calibration/cell/calibration_yaml.h"
#include "core/geometry/mesh_io.h"
#include "core/geometry/point_cloud_io.h"
#include "core/util/file_io.h"

namespace avc::report {
namespace {

namespace fs = std::filesystem;

// The report needs what a finished scan writes; a missing file most often means the folder is
// not one (or its scan stopped before reconstructing).
void RequireFile(const fs::path& path) {
  if (!fs::is_regular_file(path)) {
    throw std::runtime_error(path.string() +
                             ": missing (a finished `avc scan` or `avc demo` folder has it)");
  }
}

nlohmann::json ReadJson(const fs::path& path) {
  RequireFile(path);
  const std::string text = ReadFile(path);
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(fmt::format("{}: not JSON: {}", path.string(), e.what()));
  }
}

geometry::Mesh ReadRequiredMesh(const fs::path& path) {
  RequireFile(path);
  geometry::Mesh mesh = geometry::ReadMesh(path);  // its errors name the file
  if (const std::string problem = mesh.Validate(); !problem.empty()) {
    throw std::runtime_error(path.string() + ": " + problem);
  }
  return mesh;
}

// Runs read() when `file` exists; a missing or failing file becomes a note instead.
template <class Read>
void ReadOptional(const fs::path& dir, const std::string& file, std::vector<std::string>* notes,
                  Read read) {
  const fs::path path = dir / file;
  if (!fs::is_regular_file(path)) {
    notes->push_back(file + " is missing");
    return;
  }
  try {
    read(path);
  } catch (const std::exception& e) {
    notes->push_back(fmt::format("{} left out: {}", file, e.what()));
  }
}

}  // namespace

ReportInputs LoadReportInputs(const fs::path& scan_dir) {
  ReportInputs in;
  in.report = ReadJson(scan_dir / "report.json");
  if (!in.report.is_object()) {
    throw std::runtime_error((scan_dir / "report.json").string() + ": not a JSON object");
  }
  in.mesh = ReadRequiredMesh(scan_dir / "model" / "mesh.ply");
  ReadOptional(scan_dir, "scan.json", &in.notes,
               [&](const fs::path&) { in.scan = orchestrator::LoadScanRecord(scan_dir); });
  ReadOptional(scan_dir, "model/points.ply", &in.notes,
               [&](const fs::path& p) { in.points = geometry::ReadPointCloud(p); });
  ReadOptional(scan_dir, "model/clusters.ply", &in.notes,
               [&](const fs::path& p) { in.cluster_points = geometry::ReadPointCloud(p).size(); });
  ReadOptional(scan_dir, "cameras.json", &in.notes,
               [&](const fs::path& p) { in.cameras = camera::ReadCamerasJson(p); });
  ReadOptional(scan_dir, "calibration.yaml", &in.notes,
               [&](const fs::path& p) { in.calibration = calibration::LoadCalibration(p); });
  if (fs::exists(scan_dir / "gt_mesh.ply")) {  // a real plant has none: no note then
    ReadOptional(scan_dir, "gt_mesh.ply", &in.notes,
                 [&](const fs::path& p) { in.ground_truth = geometry::ReadMesh(p); });
  }
  return in;
}

}  // namespace avc::report
