#include "core/eval/eval_report_html.h"

#include <fmt/format.h>

#include <initializer_list>

#include "core/eval/report_format.h"
#include "core/util/web_text.h"

namespace avc::eval {
namespace {

using nlohmann::json;

std::string Row(std::initializer_list<std::string> cells, const char* tag = "td") {
  std::string row = "<tr>";
  for (const std::string& cell : cells) row += fmt::format("<{0}>{1}</{0}>", tag, cell);
  return row + "</tr>\n";
}

std::string DistanceTable(const json& report) {
  std::string html = "<table>\n" + Row({"distance (mm)", "accuracy (reconstruction &rarr; GT)",
                                        "completeness (GT &rarr; reconstruction)"},
                                       "th");
  for (const char* key : {"mean", "rmse", "median", "p90", "max"}) {
    html += Row({key, FormatMillimetres(report.at("accuracy"), key),
                 FormatMillimetres(report.at("completeness"), key)});
  }
  html += Row(
      {"chamfer mean", fmt::format("{:.3f}", report.at("chamfer_mean").get<double>() * 1e3), ""});
  return html + "</table>\n";
}

std::string ScoreTable(const json& report) {
  std::string html =
      "<table>\n" + Row({"threshold (mm)", "precision %", "recall %", "F-score %"}, "th");
  for (const json& score : report.at("scores")) {
    html += Row({fmt::format("{:g}", score.at("threshold").get<double>() * 1e3),
                 FormatPercent(score.at("precision")), FormatPercent(score.at("recall")),
                 FormatPercent(score.at("fscore"))});
  }
  return html + "</table>\n";
}

std::string OrganTable(const json& report) {
  const json& organs = report.at("organs");
  if (organs.empty()) return "<p>The ground truth has no organ labels.</p>\n";
  std::string header =
      "<tr><th>organ</th><th>GT area (mm&sup2;)</th><th>points</th>"
      "<th>accuracy mean (mm)</th><th>completeness mean (mm)</th>";
  for (const json& t : report.at("thresholds")) {
    header += fmt::format("<th>recall @ {:g} mm %</th>", t.get<double>() * 1e3);
  }
  std::string html = "<table>\n" + header + "</tr>\n";
  for (const json& organ : organs) {
    html += fmt::format("<tr><td>{}</td><td>{:.1f}</td><td>{}</td><td>{}</td><td>{}</td>",
                        EscapeHtml(organ.at("name").get<std::string>()),
                        organ.at("gt_area_m2").get<double>() * 1e6,
                        organ.at("reconstruction_points").get<size_t>(),
                        FormatMillimetres(organ.at("accuracy"), "mean"),
                        FormatMillimetres(organ.at("completeness"), "mean"));
    for (const json& score : organ.at("scores"))
      html += "<td>" + FormatPercent(score.at("recall")) + "</td>";
    html += "</tr>\n";
  }
  return html + "</table>\n";
}

std::string CoverageSection(const json& coverage) {
  std::string html = fmt::format(
      "<h2>Coverage by views</h2>\n<p>{}% of {} ground-truth samples are seen by at least {} of "
      "{} cameras (inside the image, unoccluded, grazing angle &le; {:g}&deg;).</p>\n",
      FormatPercent(coverage.at("fraction")), coverage.at("samples").get<size_t>(),
      coverage.at("min_views").get<int>(), coverage.at("cameras").get<size_t>(),
      coverage.at("max_grazing_deg").get<double>());
  if (coverage.at("organs").empty()) return html;
  html += "<table>\n" + Row({"organ", "samples", "covered %"}, "th");
  for (const json& organ : coverage.at("organs")) {
    html += Row({EscapeHtml(organ.at("name").get<std::string>()),
                 std::to_string(organ.at("samples").get<size_t>()),
                 FormatPercent(organ.at("fraction"))});
  }
  return html + "</table>\n";
}

}  // namespace

std::string RenderHtml(const json& report, const std::vector<uint8_t>& plot_png) {
  std::string html =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<title>AVC reconstruction evaluation</title>\n<style>\n"
      "body { font-family: sans-serif; margin: 2em; color: #222; }\n"
      "table { border-collapse: collapse; margin: 0.5em 0 1.5em; }\n"
      "th, td { border: 1px solid #bbb; padding: 0.25em 0.6em; text-align: right; }\n"
      "th { background: #eee; } td:first-child { text-align: left; }\n"
      "</style>\n</head>\n<body>\n<h1>Reconstruction evaluation</h1>\n";
  const json& gt = report.at("ground_truth");
  const json& rec = report.at("reconstruction");
  html += "<table>\n";
  if (const auto inputs = report.find("inputs"); inputs != report.end()) {
    html += Row({"ground truth file", EscapeHtml(inputs->value("ground_truth", ""))});
    html += Row({"reconstruction file", EscapeHtml(inputs->value("reconstruction", ""))});
  }
  html +=
      Row({"ground truth", fmt::format("{} faces, {:.6g} m&sup2;, {}, {} samples",
                                       gt.at("faces").get<size_t>(), gt.at("area_m2").get<double>(),
                                       gt.at("closed").get<bool>() ? "closed" : "open",
                                       gt.at("samples").get<size_t>())});
  html += Row({"reconstruction",
               rec.at("kind") == "mesh"
                   ? fmt::format("mesh, {} faces, {:.6g} m&sup2;, {} area samples",
                                 rec.at("faces").get<size_t>(), rec.at("area_m2").get<double>(),
                                 rec.at("evaluated_points").get<size_t>())
                   : fmt::format("point cloud, {} points", rec.at("vertices").get<size_t>())});
  html += Row({"sampling", fmt::format("{:g} per m&sup2;, seed {}",
                                       report.at("sampling").at("samples_per_m2").get<double>(),
                                       report.at("sampling").at("seed").get<uint64_t>())});
  if (report.at("area_ratio").is_number()) {
    html += Row({"area ratio", FormatPercent(report.at("area_ratio")) + " %"});
  }
  html += "</table>\n<p>" + EscapeHtml(report.at("area_note").get<std::string>()) + "</p>\n";
  if (!plot_png.empty()) {
    html += "<p><img alt=\"distance histograms and scores\" src=\"data:image/png;base64," +
            Base64Encode(plot_png) + "\"></p>\n";
  }
  html += "<h2>Distances</h2>\n" + DistanceTable(report);
  html += "<h2>Precision, recall, F-score</h2>\n" + ScoreTable(report);
  html += "<h2>Per organ</h2>\n" + OrganTable(report);
  if (const auto coverage = report.find("coverage"); coverage != report.end()) {
    html += CoverageSection(*coverage);
  }
  return html + "</body>\n</html>\n";
}

}  // namespace avc::eval
