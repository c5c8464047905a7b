#include "core/eval/report_text.h"

#include <fmt/format.h>

#include <sstream>

#include "core/eval/report_format.h"

namespace avc::eval {
namespace {

using nlohmann::json;

// Breaks text into lines of at most `width` characters at spaces.
std::string Wrap(const std::string& text, size_t width) {
  std::string out, line, word;
  std::istringstream words(text);
  while (words >> word) {
    if (!line.empty() && line.size() + 1 + word.size() > width) {
      out += line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  return out + line;
}

std::string ThresholdLabel(const json& threshold) {
  return fmt::format("{:g}mm", threshold.get<double>() * 1e3);
}

}  // namespace

std::string FormatSummary(const json& report) {
  std::string out;
  auto line = [&out](const std::string& text) { out += text + "\n"; };
  if (const auto inputs = report.find("inputs"); inputs != report.end()) {
    line(fmt::format("ground truth     {}", inputs->value("ground_truth", "")));
    line(fmt::format("reconstruction   {}", inputs->value("reconstruction", "")));
  }
  const json& gt = report.at("ground_truth");
  const json& rec = report.at("reconstruction");
  line(fmt::format("GT mesh          {} faces, {:.6g} m^2, {}, {} samples ({:g} per m^2, seed {})",
                   gt.at("faces").get<size_t>(), gt.at("area_m2").get<double>(),
                   gt.at("closed").get<bool>() ? "closed" : "open", gt.at("samples").get<size_t>(),
                   report.at("sampling").at("samples_per_m2").get<double>(),
                   report.at("sampling").at("seed").get<uint64_t>()));
  if (rec.at("kind") == "mesh") {
    line(fmt::format("reconstruction   mesh, {} faces, {:.6g} m^2, {} area samples",
                     rec.at("faces").get<size_t>(), rec.at("area_m2").get<double>(),
                     rec.at("evaluated_points").get<size_t>()));
  } else {
    line(fmt::format("reconstruction   point cloud, {} points", rec.at("vertices").get<size_t>()));
  }
  line("");
  const json& accuracy = report.at("accuracy");
  const json& completeness = report.at("completeness");
  line(fmt::format("{:<14} {:>22} {:>22}", "distance (mm)", "accuracy (rec->GT)",
                   "completeness (GT->rec)"));
  for (const char* key : {"mean", "rmse", "median", "p90", "max"}) {
    line(fmt::format("{:<14} {:>22} {:>22}", key, FormatMillimetres(accuracy, key),
                     FormatMillimetres(completeness, key)));
  }
  line(fmt::format("{:<14} {:>22.3f}", "chamfer mean",
                   report.at("chamfer_mean").get<double>() * 1e3));
  line("");
  line(
      fmt::format("{:<14} {:>10} {:>10} {:>10}", "threshold", "precision%", "recall%", "F-score%"));
  for (const json& score : report.at("scores")) {
    line(fmt::format("{:<14} {:>10} {:>10} {:>10}", ThresholdLabel(score.at("threshold")),
                     FormatPercent(score.at("precision")), FormatPercent(score.at("recall")),
                     FormatPercent(score.at("fscore"))));
  }
  line("");
  if (report.at("area_ratio").is_number()) {
    line(fmt::format("area ratio       {:.1f}% (reconstruction / ground truth)",
                     report.at("area_ratio").get<double>() * 100));
  }
  line(Wrap(report.at("area_note").get<std::string>(), 96));

  const json& organs = report.at("organs");
  if (!organs.empty()) {
    line("");
    std::string header = fmt::format("{:<12} {:>10} {:>8} {:>10} {:>10}", "organ", "GT mm^2",
                                     "points", "acc mm", "comp mm");
    for (const json& t : report.at("thresholds"))
      header += fmt::format(" {:>9}", "R@" + ThresholdLabel(t));
    line(header);
    for (const json& organ : organs) {
      std::string row =
          fmt::format("{:<12} {:>10.1f} {:>8} {:>10} {:>10}", organ.at("name").get<std::string>(),
                      organ.at("gt_area_m2").get<double>() * 1e6,
                      organ.at("reconstruction_points").get<size_t>(),
                      FormatMillimetres(organ.at("accuracy"), "mean"),
                      FormatMillimetres(organ.at("completeness"), "mean"));
      for (const json& score : organ.at("scores"))
        row += fmt::format(" {:>9}", FormatPercent(score.at("recall")));
      line(row);
    }
  }
  if (const auto coverage = report.find("coverage"); coverage != report.end()) {
    line("");
    line(
        fmt::format("coverage         {}% of {} GT samples seen by >= {} of {} cameras at <= {:g} "
                    "deg grazing",
                    FormatPercent(coverage->at("fraction")), coverage->at("samples").get<size_t>(),
                    coverage->at("min_views").get<int>(), coverage->at("cameras").get<size_t>(),
                    coverage->at("max_grazing_deg").get<double>()));
    for (const json& organ : coverage->at("organs")) {
      line(fmt::format("  {:<14} {:>6}% of {} samples", organ.at("name").get<std::string>(),
                       FormatPercent(organ.at("fraction")), organ.at("samples").get<size_t>()));
    }
  }
  return out;
}

}  // namespace avc::eval
