#include "core/eval/leaf_figures.h"

#include <fmt/format.h>

#include <cmath>

#include "core/geometry/mesh.h"

namespace avc::eval {
namespace {

using Json = nlohmann::json;

double ScoreAt(const Json& scores, double threshold, const char* key) {
  for (const Json& s : scores) {
    if (std::abs(s["threshold"].get<double>() - threshold) < 1e-9) return s[key].get<double>();
  }
  return 0;
}

}  // namespace

Json LeafFigures(const Json& evaluation) {
  double gt_area = 0, area = 0, accuracy_sum = 0, recall_sum = 0, precision_sum = 0;
  double points = 0, samples = 0;
  for (const Json& organ : evaluation["organs"]) {
    if (!geometry::labels::IsLeaf(organ["label"].get<int>())) continue;
    const double n = organ["reconstruction_points"].get<double>();
    const double m = organ["gt_samples"].get<double>();
    gt_area += organ["gt_area_m2"].get<double>();
    area += organ["reconstructed_area_m2"].get<double>();
    if (n > 0) accuracy_sum += n * organ["accuracy"]["mean"].get<double>();
    precision_sum += n * ScoreAt(organ["scores"], 0.002, "precision");
    recall_sum += m * ScoreAt(organ["scores"], 0.002, "recall");
    points += n;
    samples += m;
  }
  const double precision = points > 0 ? precision_sum / points : 0;
  const double recall = samples > 0 ? recall_sum / samples : 0;
  return {
      {"area_ratio", gt_area > 0 ? area / gt_area : 0},
      {"accuracy_mean_mm", points > 0 ? 1e3 * accuracy_sum / points : 0},
      {"precision_2mm", precision},
      {"recall_2mm", recall},
      {"fscore_2mm", precision + recall > 0 ? 2 * precision * recall / (precision + recall) : 0}};
}

std::string FormatLeafFigures(const Json& figures) {
  return fmt::format(
      "the leaves: {:.1f} % of their area, precision {:.1f} % and recall {:.1f} % at 2 mm, mean "
      "error {:.2f} mm\n",
      100 * figures.at("area_ratio").get<double>(), 100 * figures.at("precision_2mm").get<double>(),
      100 * figures.at("recall_2mm").get<double>(), figures.at("accuracy_mean_mm").get<double>());
}

}  // namespace avc::eval
