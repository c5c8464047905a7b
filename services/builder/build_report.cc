#include "services/builder/build_report.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <sys/resource.h>

#include "core/geometry/mesh_io.h"

namespace avc::builder {
namespace {

double PeakMemoryMb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // kB on Linux
}

nlohmann::ordered_json StatsJson(const eval::DistanceStats& stats) {
  return {{"count", stats.count},
          {"mean_m", stats.mean},
          {"rmse_m", stats.rmse},
          {"median_m", stats.median},
          {"p90_m", stats.p90}};
}

}  // namespace

BuildReport MakeBuildReport(const Reconstruction& reconstruction, MvsMethod method,
                            const std::filesystem::path& ground_truth_mesh,
                            const Eigen::Matrix3d& ground_truth_to_world) {
  BuildReport report;
  report.method = MvsMethodName(method);
  report.images = reconstruction.masks.views.size();
  report.points = reconstruction.points.size();
  report.points_per_image =
      report.images == 0 ? 0 : static_cast<double>(report.points) / report.images;
  report.merged_points = reconstruction.merged.size();
  report.outliers_outside_proxy =
      reconstruction.points_outside_proxy + reconstruction.merged.outside_proxy;
  report.outliers_in_sparse_voxels = reconstruction.merged.in_sparse_voxels;
  report.voxel_size = reconstruction.proxy.voxel_size();
  report.voxels = reconstruction.proxy.Counts();
  report.timings = reconstruction.timings;
  report.masks = reconstruction.masks;
  report.soil = reconstruction.soil;
  report.support = reconstruction.support;
  report.soil_not_found = reconstruction.soil_not_found;
  if (!ground_truth_mesh.empty() && report.points > 0) {
    geometry::Mesh truth = geometry::ReadMesh(ground_truth_mesh);
    const Eigen::Matrix3f to_world = ground_truth_to_world.cast<float>();
    for (Eigen::Vector3f& vertex : truth.vertices) vertex = to_world * vertex;
    eval::EvalOptions options;
    options.thresholds = {0.0005, 0.001, 0.002, 0.005};
    eval::EvalResult result = eval::EvaluatePointCloud(truth, reconstruction.points.cloud, options);
    // The per-point arrays are for plots; the report keeps the summaries.
    result.accuracy_distances.clear();
    result.nearest_gt_face.clear();
    result.completeness_distances.clear();
    result.gt_samples = {};
    report.accuracy = std::move(result);
  }
  report.peak_memory_mb = PeakMemoryMb();
  return report;
}

nlohmann::ordered_json BuildReportToJson(const BuildReport& report) {
  nlohmann::ordered_json json = {
      {"method", report.method},
      {"images", report.images},
      {"points", report.points},
      {"points_per_image", report.points_per_image},
      {"merged",
       {{"points", report.merged_points},
        {"outliers_outside_proxy", report.outliers_outside_proxy},
        {"outliers_in_sparse_voxels", report.outliers_in_sparse_voxels}}},
      {"proxy",
       {{"voxel_size_m", report.voxel_size},
        {"occupied", report.voxels.occupied},
        {"free", report.voxels.free},
        {"unknown", report.voxels.unknown}}}};
  if (report.accuracy) {
    const eval::EvalResult& a = *report.accuracy;
    nlohmann::ordered_json scores = nlohmann::ordered_json::array();
    for (const eval::ThresholdScore& s : a.scores) {
      scores.push_back({{"threshold_m", s.threshold},
                        {"precision", s.precision},
                        {"recall", s.recall},
                        {"fscore", s.fscore}});
    }
    json["ground_truth"] = {{"accuracy", StatsJson(a.accuracy)},
                            {"completeness", StatsJson(a.completeness)},
                            {"scores", scores}};
  }
  nlohmann::ordered_json masks = nlohmann::ordered_json::array();
  for (const segmentation::ViewMask& m : report.masks.views) {
    masks.push_back({{"view", m.view},
                     {"given", m.given},
                     {"method", m.given ? "given" : segmentation::MaskMethodName(m.method)},
                     {"plant_fraction", m.plant_fraction}});
  }
  json["masks"] = masks;
  json["masks_without_plant"] = MasksWithoutPlant(report.masks);
  json["masks_mostly_plant"] = MasksMostlyPlant(report.masks);
  json["soil"] = report.soil ? nlohmann::ordered_json(SoilLevelToJson(*report.soil)) : nullptr;
  if (!report.soil) json["soil_not_found"] = report.soil_not_found;
  json["support"] = report.support
                        ? nlohmann::ordered_json{{"top_z_m", report.support->z},
                                                 {"jump", report.support->jump},
                                                 {"mass_fraction", report.support->mass_fraction}}
                        : nullptr;
  nlohmann::ordered_json timings = nlohmann::ordered_json::object();
  for (const StageTime& t : report.timings) timings[t.stage + "_s"] = t.seconds;
  json["timings"] = timings;
  json["peak_memory_mb"] = report.peak_memory_mb;
  return json;
}

std::vector<std::string> MaskViewsWhere(const segmentation::MaskSummary& masks,
                                        const std::function<bool(double)>& test) {
  std::vector<std::string> views;
  for (const segmentation::ViewMask& view : masks.views) {
    if (test(view.plant_fraction)) views.push_back(view.view);
  }
  return views;
}

std::vector<std::string> MasksWithoutPlant(const segmentation::MaskSummary& masks) {
  return MaskViewsWhere(masks, [](double f) { return f == 0; });
}

std::vector<std::string> MasksMostlyPlant(const segmentation::MaskSummary& masks) {
  return MaskViewsWhere(masks, [](double f) { return f >= kMostlyPlantFraction; });
}

std::string DescribeMaskProblems(const segmentation::MaskSummary& masks) {
  std::string text;
  const auto none = MasksWithoutPlant(masks);
  if (!none.empty()) {
    text += fmt::format("warning: {} of {} masks show no plant ({}); left out of the proxy\n",
                        none.size(), masks.views.size(), fmt::join(none, ", "));
  }
  const auto all = MasksMostlyPlant(masks);
  if (!all.empty()) {
    text += fmt::format(
        "warning: {} of {} masks are at least {:.0f} % plant ({}): the plant is not told from its "
        "background there, so those views carve nothing; check them or give masks\n",
        all.size(), masks.views.size(), 100 * kMostlyPlantFraction, fmt::join(all, ", "));
  }
  return text;
}

std::string BuildReportToText(const BuildReport& report) {
  std::string text = fmt::format(
      "{} images, {} points ({:.0f} per image, {}); proxy {:.2f} mm voxels, {} occupied\n",
      report.images, report.points, report.points_per_image, report.method, report.voxel_size * 1e3,
      report.voxels.occupied);
  if (report.points > 0) {
    text += fmt::format(
        "merged into the proxy: {} points ({} outside it, {} in voxels with too few)\n",
        report.merged_points, report.outliers_outside_proxy, report.outliers_in_sparse_voxels);
  }
  text += DescribeMaskProblems(report.masks);
  if (report.support) text += DescribeSupport(*report.support) + "\n";
  if (report.soil) {
    text += fmt::format("soil surface at z = {:.1f} mm (contrast {:.2f}, {} patches)\n",
                        report.soil->z * 1e3, report.soil->contrast, report.soil->patches);
  } else {
    text += fmt::format("soil surface not found ({}): plant height from the {}\n",
                        report.soil_not_found, report.support ? "support's top" : "proxy's base");
  }
  if (report.accuracy) {
    const eval::EvalResult& a = *report.accuracy;
    text += fmt::format("against the ground truth: mean distance {:.3f} mm (RMS {:.3f} mm)",
                        a.accuracy.mean * 1e3, a.accuracy.rmse * 1e3);
    for (const eval::ThresholdScore& s : a.scores) {
      text += fmt::format("; P/R@{:g}mm {:.3f}/{:.3f}", s.threshold * 1e3, s.precision, s.recall);
    }
    text += "\n";
  }
  double total = 0;
  std::string stages;
  for (const StageTime& t : report.timings) {
    total += t.seconds;
    stages += fmt::format(" {} {:.2f} s,", t.stage, t.seconds);
  }
  if (!stages.empty()) stages.pop_back();
  text += fmt::format("time {:.2f} s ({}); peak memory {:.0f} MB\n", total, stages.substr(1),
                      report.peak_memory_mb);
  return text;
}

}  // namespace avc::builder
