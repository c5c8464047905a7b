#include "report/report_sections.h"

#include <fmt/format.h>

#include <cmath>
#include <ctime>
#include <filesystem>

#include "report/report_encode.h"
#include "report/report_svg.h"

namespace avc::report {
namespace {

using nlohmann::json;

// The number at `key` of `object` times `scale`, formatted; "–" when absent.
std::string Number(const json& object, const char* key, double scale, int decimals) {
  if (!object.is_object() || !object.contains(key) || !object[key].is_number()) return "–";
  return fmt::format("{:.{}f}", object[key].get<double>() * scale, decimals);
}

std::string Figure(const std::string& label, const std::string& value, const std::string& unit) {
  return fmt::format("<div class=\"figure\">{}<b>{} {}</b></div>\n", EscapeHtml(label), value,
                     unit);
}

std::string Cell(const std::string& text) { return "<td>" + EscapeHtml(text) + "</td>"; }
std::string NumCell(const std::string& text) { return "<td class=\"num\">" + text + "</td>"; }

// A list item per entry of a JSON array (strings as they are, anything else as JSON), opened
// with `open` (a <ul> tag).
std::string TextList(const json& items, const char* open) {
  std::string html = std::string(open) + "\n";
  for (const json& item : items) {
    html +=
        "<li>" + EscapeHtml(item.is_string() ? item.get<std::string>() : item.dump()) + "</li>\n";
  }
  return html + "</ul>\n";
}

// scan.json's creation time, in UTC so the page does not depend on where it is made.
std::string Date(int64_t utime) {
  if (utime <= 0) return "unknown";
  const std::time_t seconds = static_cast<std::time_t>(utime / 1000000);
  std::tm tm{};
  gmtime_r(&seconds, &tm);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M:%S UTC", &tm);
  return text;
}

std::string GroundTruth(const json& truth) {
  std::string html =
      "<h3>Against the ground truth</h3>\n<table><tr><th></th><th>mean (mm)</th><th>RMSE "
      "(mm)</th><th>median (mm)</th><th>90 % (mm)</th></tr>\n";
  for (const char* side : {"accuracy", "completeness"}) {
    if (!truth.contains(side)) continue;
    const json& s = truth[side];
    html += "<tr>" + Cell(side) + NumCell(Number(s, "mean_m", 1e3, 2)) +
            NumCell(Number(s, "rmse_m", 1e3, 2)) + NumCell(Number(s, "median_m", 1e3, 2)) +
            NumCell(Number(s, "p90_m", 1e3, 2)) + "</tr>\n";
  }
  html += "</table>\n";
  if (truth.contains("scores") && truth["scores"].is_array()) {
    html +=
        "<table><tr><th>threshold "
        "(mm)</th><th>precision</th><th>recall</th><th>F-score</th></tr>\n";
    for (const json& s : truth["scores"]) {
      html += "<tr>" + NumCell(Number(s, "threshold_m", 1e3, 1)) +
              NumCell(Number(s, "precision", 1, 3)) + NumCell(Number(s, "recall", 1, 3)) +
              NumCell(Number(s, "fscore", 1, 3)) + "</tr>\n";
    }
    html += "</table>\n";
  }
  return html;
}

}  // namespace

std::string HeaderSection(const ReportInputs& in) {
  const json& r = in.report;
  std::string html = fmt::format("<h1>Scan {}</h1>\n<p class=\"meta\">",
                                 EscapeHtml(r.value("scan_id", std::string("(no id)"))));
  if (in.scan) {
    html += fmt::format("Started {} · state {}", Date(in.scan->created_utime),
                        EscapeHtml(std::string(orchestrator::StateName(in.scan->state))));
    if (!in.scan->cell.empty()) html += " · cell " + EscapeHtml(in.scan->cell);
  } else {
    html += "No scan.json: date and state unknown";
  }
  const json images = r.value("images", json::object());
  html += fmt::format(" · images captured {}, kept {}</p>\n", Number(images, "captured", 1, 0),
                      Number(images, "kept", 1, 0));
  return html;
}

std::string KeyFiguresSection(const ReportInputs& in) {
  const json traits = in.report.value("traits", json::object());
  const json build = in.report.value("build", json::object());
  std::string html = "<h2>Key figures</h2>\n<div class=\"figures\">\n";
  html += Figure("leaf area", Number(traits, "total_area_m2", 1e4, 1), "cm²");
  // The builder's soil level (build.json "soil") is where the height starts; without it, the
  // proxy's base.
  const bool from_soil = build.contains("soil") && build["soil"].is_object();
  html += Figure(from_soil ? "height above the soil" : "height above the proxy's base",
                 Number(traits, "height_m", 1e2, 1), "cm");
  html += Figure("width", Number(traits, "width_m", 1e2, 1), "cm");
  html += Figure("hull volume", Number(traits, "hull_volume_m3", 1e6, 1), "cm³");
  const size_t clusters = traits.contains("clusters") ? traits["clusters"].size() : 0;
  html += Figure("leaves / clusters", std::to_string(clusters), "");
  html += Figure("mesh faces", std::to_string(in.mesh.num_faces()), "");
  html += Figure("MVS points", Number(build, "points", 1, 0), "");
  if (build.contains("merged"))
    html += Figure("merged points", Number(build["merged"], "points", 1, 0), "");
  html += "</div>\n";
  if (build.contains("ground_truth")) html += GroundTruth(build["ground_truth"]);
  return html;
}

std::string TimingsSection(const ReportInputs& in) {
  const json phases = in.report.value("phases", json::array());
  if (!phases.is_array() || phases.empty()) return "<h2>Timings</h2>\n<p>No phases recorded.</p>\n";
  std::vector<std::pair<std::string, double>> bars;
  std::string table = "<table><tr><th>phase</th><th>seconds</th></tr>\n";
  double total = 0;
  for (const json& phase : phases) {
    const std::string state = phase.value("state", std::string("?"));
    const double seconds = phase.value("seconds", 0.0);
    bars.emplace_back(state, seconds);
    total += seconds;
    table += "<tr>" + Cell(state) + NumCell(fmt::format("{:.2f}", seconds)) + "</tr>\n";
  }
  table += fmt::format("<tr><th>total</th><td class=\"num\">{:.2f}</td></tr>\n</table>\n", total);
  return "<h2>Timings</h2>\n" + table + BarChartSvg(bars, "s");
}

std::string ViewsSection(const ReportInputs& in) {
  std::string html = "<h2>Views</h2>\n";
  if (!in.scan) {
    html += "<table><tr><th>image</th></tr>\n";
    for (const camera::NamedCamera& cam : in.cameras) html += "<tr>" + Cell(cam.name) + "</tr>\n";
    return html + "</table>\n";
  }
  html +=
      "<table><tr><th>#</th><th>image</th><th>phase</th><th>table (°)</th><th>reason</th>"
      "<th>kept</th></tr>\n";
  for (const orchestrator::CaptureRecord& c : in.scan->captures) {
    html += fmt::format("<tr{}>", c.kept ? "" : " class=\"dropped\"") +
            NumCell(std::to_string(c.index)) +
            Cell(std::filesystem::path(c.file).filename().string()) + Cell(c.phase) +
            NumCell(fmt::format("{:.1f}", c.table_angle * 180 / M_PI)) + Cell(c.reason) +
            Cell(c.kept ? "yes" : "no") + "</tr>\n";
  }
  return html + "</table>\n";
}

std::string ClustersSection(const ReportInputs& in) {
  const json traits = in.report.value("traits", json::object());
  if (!traits.contains("clusters") || !traits["clusters"].is_array()) return "";
  std::string html =
      "<h2>Clusters</h2>\n<table><tr><th>cluster</th><th>area (cm²)</th><th>inclination "
      "(°)</th><th>azimuth (°)</th></tr>\n";
  for (const json& c : traits["clusters"]) {
    const int id = c.value("cluster", -1);
    html += fmt::format("<tr><td><span class=\"swatch\" style=\"background:{}\"></span> {}</td>",
                        CssColour(ClusterColour(id)), id) +
            NumCell(Number(c, "area_m2", 1e4, 2)) + NumCell(Number(c, "inclination_deg", 1, 1)) +
            NumCell(Number(c, "azimuth_deg", 1, 1)) + "</tr>\n";
  }
  html += "</table>\n";
  html += fmt::format("<p>Mean curvature {} per m; faces {}.</p>\n",
                      Number(traits, "mean_curvature_per_m", 1, 2), Number(traits, "faces", 1, 0));
  return html;
}

std::string SurfaceSection(const ReportInputs& in) {
  const json surface = in.report.value("surface", json::object());
  if (!surface.is_object() || surface.empty()) return "";
  std::string html = "<h2>Surface</h2>\n";
  html += fmt::format(
      "<p>{} clusters of {} points ({} left out: too few or collinear to triangulate) became {} "
      "cells; {} stitch faces joined them into {} connected pieces.</p>\n",
      Number(surface, "clusters", 1, 0), Number(surface, "points_used", 1, 0),
      Number(surface, "points_left_out", 1, 0), Number(surface, "cells", 1, 0),
      Number(surface, "stitch_faces", 1, 0), Number(surface, "components", 1, 0));
  const json area = surface.value("area_m2_after_phase", json::object());
  html += "<table><tr><th>after phase</th><th>area (cm²)</th></tr>\n";
  const char* phases[][2] = {{"1", "1: triangulated cells"},
                             {"2", "2: outlines grown"},
                             {"3", "3: cleaned and smoothed"},
                             {"4", "4: cells merged"}};
  for (const auto& [key, label] : phases) {
    html += "<tr>" + Cell(label) + NumCell(Number(area, key, 1e4, 1)) + "</tr>\n";
  }
  html += "</table>\n";
  const json warnings = surface.value("warnings", json::array());
  if (warnings.is_array() && !warnings.empty()) html += TextList(warnings, "<ul class=\"notes\">");
  return html;
}

std::string CalibrationSection(const ReportInputs& in) {
  if (!in.calibration) return "";
  const calibration::CalibrationResiduals& r = in.calibration->residuals;
  std::string html = fmt::format(
      "<h2>Calibration residuals</h2>\n<p>Intrinsics RMS {:.3f} px · hand-eye RMS {:.3f} px, "
      "{:.3f}° / {:.2f} mm · turntable centre RMS {:.2f} mm over {} angles</p>\n",
      r.intrinsics_rms_px, r.hand_eye_rms_px, r.hand_eye_rotation_deg, r.hand_eye_translation_mm,
      r.turntable_centre_rms_mm, r.turntable_angles);
  if (!r.view_names.empty()) {
    html += "<table><tr><th>view</th><th>RMS (px)</th></tr>\n";
    for (size_t i = 0; i < r.view_names.size(); ++i) {
      html += "<tr>" + Cell(r.view_names[i]) +
              NumCell(i < r.view_rms_px.size() ? fmt::format("{:.3f}", r.view_rms_px[i]) : "–") +
              "</tr>\n";
    }
    html += "</table>\n";
  }
  for (const std::string& why : r.rejected) html += "<p>Left out: " + EscapeHtml(why) + "</p>\n";
  return html;
}

std::string PlannerSection(const ReportInputs& in) {
  const json planner = in.report.value("planner", json::object());
  std::string html = "<h2>Planner</h2>\n";
  html += fmt::format("<p>Patches {}, failing at the end {}.</p>\n",
                      Number(planner, "patches", 1, 0), Number(planner, "failing_patches", 1, 0));
  for (const char* key : {"planner_notes", "notes"}) {
    if (!planner.contains(key) || !planner[key].is_array()) continue;
    html += TextList(planner[key], "<ul>");
  }
  return html;
}

std::string ConfigurationSection(const ReportInputs& in) {
  const json stages = in.report.value("stages", json::object());
  if (stages.empty()) return "";
  std::string html =
      "<h2>Configuration</h2>\n<p>The options each stage's service ran with (`--config FILE` "
      "takes these files).</p>\n<table>\n<tr><th>Stage</th><th>Service</th><th>SHA-256</th>"
      "<th>File</th></tr>\n";
  for (const auto& [stage, entry] : stages.items()) {
    const std::string sha = entry.value("config_sha256", std::string());
    html += "<tr>" + Cell(stage) + Cell(entry.value("service", std::string())) +
            Cell(sha.empty() ? "not named" : sha.substr(0, 16)) +
            Cell(entry.value("config_file", std::string("-"))) + "</tr>\n";
  }
  return html + "</table>\n";
}

std::string NotesSection(const ReportInputs& in) {
  std::string html = "<h2>Inputs</h2>\n";
  if (in.cluster_points) {
    html += fmt::format("<p>model/clusters.ply: {} merged points.</p>\n", *in.cluster_points);
  }
  if (in.notes.empty()) return html + "<p>Every input of the report was found.</p>\n";
  html += "<ul class=\"notes\">\n";
  for (const std::string& note : in.notes) html += "<li>" + EscapeHtml(note) + "</li>\n";
  return html + "</ul>\n";
}

}  // namespace avc::report
