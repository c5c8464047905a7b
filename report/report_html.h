#pragma once

// report.html: one self-contained page about a finished scan that works offline (three.js and
// every datum inlined; no URL is fetched). Header (scan id, date, state, images), the plant's key
// figures and, for simulated scans, the scores against the ground truth; an interactive 3-D view
// of the mesh with its MVS points and the kept cameras; static SVG renders of the mesh from the
// front, side and top (the view without WebGL, and on paper); phase timings; the views; traits
// per cluster; calibration residuals; the planner's notes. Same scan directory → same bytes.

#include <filesystem>
#include <string>

namespace avc::report {

// The page for the scan in scan_dir. Throws std::runtime_error naming the file when report.json
// or model/mesh.ply is missing or unreadable; other missing inputs are noted in the page.
std::string ReportHtml(const std::filesystem::path& scan_dir);

// Writes ReportHtml(scan_dir) to scan_dir/report.html, atomically.
void WriteReportHtml(const std::filesystem::path& scan_dir);

}  // namespace avc::report
