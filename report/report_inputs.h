#pragma once

// What the scan report (report_html.h) is made from, read from a finished scan directory.
// report.json and model/mesh.ply are required; every other file is optional and, when missing
// or unreadable, left out with a sentence in `notes` so the page says what it could not show.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/calibration/cell/cell_calibration.h"
#include "core/camera/camera_io.h"
#include "core/geometry/mesh.h"
#include "core/geometry/point_cloud.h"
#include "orchestrator/scan_record.h"

namespace avc::report {

struct ReportInputs {
  nlohmann::json report;  // report.json
  geometry::Mesh mesh;    // model/mesh.ply
  std::optional<orchestrator::ScanRecord> scan;
  std::optional<geometry::PointCloud> points;  // model/points.ply
  std::optional<size_t> cluster_points;        // points in model/clusters.ply
  std::vector<camera::NamedCamera> cameras;    // cameras.json (empty when absent)
  std::optional<calibration::CellCalibration> calibration;
  std::optional<geometry::Mesh> ground_truth;  // gt_mesh.ply: simulated scans only
  std::vector<std::string> notes;              // optional inputs left out, and why
};

// Throws std::runtime_error naming the file when report.json or model/mesh.ply is missing or
// unreadable.
ReportInputs LoadReportInputs(const std::filesystem::path& scan_dir);

}  // namespace avc::report
