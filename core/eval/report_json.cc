#include "core/eval/report_json.h"

namespace avc::eval {
namespace {

nlohmann::json ToJson(const DistanceStats& stats) {
  if (stats.count == 0) return {{"count", 0}};
  return {{"count", stats.count},   {"rmse", stats.rmse}, {"mean", stats.mean},
          {"median", stats.median}, {"p90", stats.p90},   {"max", stats.max}};
}

nlohmann::json ToJson(const std::vector<ThresholdScore>& scores) {
  nlohmann::json list = nlohmann::json::array();
  for (const ThresholdScore& score : scores) {
    list.push_back({{"threshold", score.threshold},
                    {"precision", score.precision},
                    {"recall", score.recall},
                    {"fscore", score.fscore}});
  }
  return list;
}

template <class T>
nlohmann::json OrNull(const std::optional<T>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

}  // namespace

nlohmann::json ToJson(const EvalResult& result) {
  nlohmann::json organs = nlohmann::json::array();
  for (const OrganEval& organ : result.organs) {
    organs.push_back({{"label", organ.label},
                      {"name", organ.name},
                      {"gt_area_m2", organ.gt_area},
                      {"gt_samples", organ.completeness.count},
                      {"reconstruction_points", organ.accuracy.count},
                      {"completeness", ToJson(organ.completeness)},
                      {"accuracy", ToJson(organ.accuracy)},
                      {"scores", ToJson(organ.scores)},
                      {"reconstructed_area_m2", OrNull(organ.reconstructed_area)}});
  }
  return {{"units", "metres"},
          {"sampling",
           {{"samples_per_m2", result.samples_per_m2},
            {"seed", result.seed},
            {"gt_sample_seed", result.gt_sample_seed},
            {"reconstruction_sample_seed", OrNull(result.reconstruction_sample_seed)}}},
          {"ground_truth",
           {{"vertices", result.gt_vertices},
            {"faces", result.gt_faces},
            {"area_m2", result.gt_area},
            {"boundary_edges", result.gt_boundary_edges},
            {"closed", result.gt_closed},
            {"samples", result.gt_samples.size()}}},
          {"reconstruction",
           {{"kind", result.reconstruction_is_mesh ? "mesh" : "point_cloud"},
            {"vertices", result.reconstruction_vertices},
            {"faces", result.reconstruction_faces},
            {"area_m2", OrNull(result.reconstruction_area)},
            {"evaluated_points", result.reconstruction_points}}},
          {"accuracy", ToJson(result.accuracy)},
          {"completeness", ToJson(result.completeness)},
          {"chamfer_mean", result.chamfer},
          {"thresholds", result.thresholds},
          {"scores", ToJson(result.scores)},
          {"area_ratio", OrNull(result.area_ratio)},
          {"area_note", result.area_note},
          {"organs", organs}};
}

nlohmann::json ToJson(const CoverageResult& result) {
  nlohmann::json organs = nlohmann::json::array();
  for (const OrganCoverage& organ : result.organs) {
    organs.push_back({{"label", organ.label},
                      {"name", organ.name},
                      {"samples", organ.samples},
                      {"covered", organ.covered},
                      {"fraction", organ.fraction}});
  }
  return {{"cameras", result.cameras},
          {"min_views", result.options.min_views},
          {"max_grazing_deg", result.options.max_grazing_deg},
          {"occlusion_epsilon_m", result.options.occlusion_epsilon},
          {"samples", result.samples},
          {"covered", result.covered},
          {"fraction", result.fraction},
          {"view_count_histogram", result.view_count_histogram},
          {"organs", organs}};
}

}  // namespace avc::eval
