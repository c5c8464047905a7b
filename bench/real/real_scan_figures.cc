#include "bench/real/real_scan_figures.h"

#include <fmt/format.h>

#include <algorithm>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>

#include "bench/real/reference_silhouette.h"
#include "core/dataset/dataset_reader.h"
#include "core/eval/metrics.h"
#include "core/geometry/mesh_io.h"
#include "core/geometry/point_cloud_io.h"
#include "core/ppr/octree_voxels.h"
#include "core/surface/mesh_topology.h"
#include "core/surface/thin_organs.h"
#include "core/traits/plant_traits.h"
#include "core/util/file_io.h"
#include "core/util/json_file.h"
#include "core/util/upper_median.h"

namespace avc::bench {
namespace {

namespace fs = std::filesystem;

const std::vector<double> kThresholds = {0.001, 0.002, 0.005};
// Taubin pairs on the proxy's voxel boundary: enough to round the staircase of 1-3 voxel wide
// organs without shrinking them.
constexpr int kProxySurfaceSmoothing = 10;
// As carved, and moved half a voxel in (the hull's margin round a thin organ).
constexpr double kProxySurfaceInwardVoxels[] = {0.0, 0.5};

nlohmann::json Scores(const eval::EvalResult& result) {
  nlohmann::json json = nlohmann::json::object();
  for (const eval::ThresholdScore& score : result.scores) {
    json[fmt::format("{:g}mm", score.threshold * 1e3)] = {
        {"precision", score.precision}, {"recall", score.recall}, {"fscore", score.fscore}};
  }
  return json;
}

nlohmann::json MaskFigures(const dataset::ViewSet& set, const fs::path& output,
                           const geometry::Mesh& reference, double tolerance_px) {
  nlohmann::json views = nlohmann::json::array();
  std::vector<double> off, covered, fraction;
  for (const dataset::View& view : set.views) {
    const fs::path file = output / "masks" / fs::path(view.name).replace_extension(".png");
    const cv::Mat mask = cv::imread(file.string(), cv::IMREAD_GRAYSCALE);
    if (mask.empty()) throw std::runtime_error(file.string() + ": missing or unreadable mask");
    const MaskAgainstReference figures =
        CompareMask(mask, ReferenceSilhouette(reference, view.camera), tolerance_px);
    views.push_back({{"view", view.name},
                     {"plant_fraction", figures.plant_fraction},
                     {"off_reference", figures.off_reference},
                     {"reference_covered", figures.reference_covered}});
    off.push_back(figures.off_reference);
    covered.push_back(figures.reference_covered);
    fraction.push_back(figures.plant_fraction);
  }
  return {{"tolerance_px", tolerance_px},
          {"plant_fraction_median", UpperMedian(fraction)},
          {"off_reference_median", UpperMedian(off)},
          {"off_reference_max", *std::max_element(off.begin(), off.end())},
          {"reference_covered_median", UpperMedian(covered)},
          {"reference_covered_min", *std::min_element(covered.begin(), covered.end())},
          {"views", views}};
}

// "  name        P / R at 1 mm  ... at 2 mm  ... at 5 mm".
std::string ScoreLine(const std::string& name, const nlohmann::json& scores) {
  const auto score = [&](const char* at, const char* what) {
    return scores.at(at).at(what).get<double>();
  };
  return fmt::format("  {:<11} {:.3f} / {:.3f}  {:.3f} / {:.3f}  {:.3f} / {:.3f}\n", name,
                     score("1mm", "precision"), score("1mm", "recall"), score("2mm", "precision"),
                     score("2mm", "recall"), score("5mm", "precision"), score("5mm", "recall"));
}

}  // namespace

nlohmann::json ReadStageTimes(const fs::path& output) {
  const nlohmann::json build = ReadJsonFile(output / "build.json");
  nlohmann::json json = build.at("timings");
  json["views"] = build.at("images");
  json["points"] = build.at("points");
  return json;
}

nlohmann::json MeasureRealScan(const fs::path& dataset, const fs::path& output,
                               const fs::path& reference_file,
                               const RealScanFigureOptions& options) {
  const dataset::ViewSet set =
      dataset::ReadDataset(dataset, {.load_masks = false, .stride = options.stride});
  geometry::Mesh reference = geometry::ReadMesh(reference_file);
  const Eigen::Matrix3f to_world = set.FileToWorld().cast<float>();
  for (Eigen::Vector3f& vertex : reference.vertices) vertex = to_world * vertex;

  eval::EvalOptions eval_options;
  eval_options.thresholds = kThresholds;
  const geometry::PointCloud points = geometry::ReadPointCloud(output / "points.ply");
  const eval::EvalResult point_eval = eval::EvaluatePointCloud(reference, points, eval_options);
  const geometry::Mesh mesh = geometry::ReadMesh(output / "mesh.ply");
  const eval::EvalResult mesh_eval = eval::EvaluateMesh(reference, mesh, eval_options);
  const nlohmann::json surface = ReadJsonFile(output / "surface.json");
  const nlohmann::json traits = ReadJsonFile(output / "traits.json");
  const traits::PlantTraits reference_traits = traits::MeasureTraits(reference);

  nlohmann::json json;
  json["dataset_unit"] = set.unit;
  json["points"] = {{"count", points.size()}, {"scores", Scores(point_eval)}};
  json["mesh"] = {{"faces", mesh.num_faces()},
                  {"pieces", surface.at("components")},
                  {"area_m2", mesh_eval.reconstruction_area.value_or(0)},
                  {"reference_area_m2", mesh_eval.gt_area},
                  {"area_ratio", mesh_eval.area_ratio.value_or(0)},
                  {"scores", Scores(mesh_eval)}};
  json["traits"] = {{"height_m", traits.at("height_m")},
                    {"reference_height_m", reference_traits.height},
                    {"width_m", traits.at("width_m")},
                    {"reference_width_m", reference_traits.width}};
  json["masks"] = MaskFigures(set, output, reference, options.tolerance_px);

  const fs::path proxy_file = output / "ppr.bt";
  const mvs::MvsBounds proxy =
      ppr::OccupiedVoxelsFromBinary(ReadFile(proxy_file), 0.0, proxy_file.string());
  std::vector<Eigen::Vector3i> voxels;
  for (const Eigen::Vector3f& centre : proxy.occupied_centres) {
    voxels.push_back((centre.cast<double>() / proxy.voxel_size).array().floor().cast<int>());
  }
  json["proxy_surfaces"] = nlohmann::json::array();
  for (double inward : kProxySurfaceInwardVoxels) {
    const geometry::Mesh proxy_surface =
        surface::VoxelSurface(voxels, voxels, proxy.voxel_size, kProxySurfaceSmoothing, inward);
    const eval::EvalResult proxy_eval = eval::EvaluateMesh(reference, proxy_surface, eval_options);
    int pieces = 0;
    surface::FaceComponents(proxy_surface, &pieces);
    json["proxy_surfaces"].push_back({{"inward_voxels", inward},
                                      {"faces", proxy_surface.num_faces()},
                                      {"pieces", pieces},
                                      {"smoothing_iterations", kProxySurfaceSmoothing},
                                      {"area_ratio", proxy_eval.area_ratio.value_or(0)},
                                      {"scores", Scores(proxy_eval)}});
  }
  return json;
}

std::string FormatRealScanFigures(const nlohmann::json& figures) {
  const nlohmann::json& p = figures["points"]["scores"];
  const nlohmann::json& m = figures["mesh"]["scores"];
  const nlohmann::json& t = figures["traits"];
  const nlohmann::json& masks = figures["masks"];
  std::string text = "Against the reference mesh (millimetres; precision / recall):\n";
  text += "              1 mm           2 mm           5 mm\n";
  for (const auto& [name, scores] : {std::pair{"MVS points", &p}, std::pair{"mesh", &m}}) {
    text += ScoreLine(name, *scores);
  }
  for (const nlohmann::json& surface : figures["proxy_surfaces"]) {
    text += ScoreLine(fmt::format("proxy-{:.1f}", surface["inward_voxels"].get<double>()),
                      surface["scores"]);
  }
  text += fmt::format(
      "  {} MVS points; mesh {} faces in {} pieces, area {:.1f} cm^2 = {:.2f}x the reference's "
      "{:.1f} cm^2\n",
      figures["points"]["count"].get<size_t>(), figures["mesh"]["faces"].get<size_t>(),
      figures["mesh"]["pieces"].get<int>(), 1e4 * figures["mesh"]["area_m2"].get<double>(),
      figures["mesh"]["area_ratio"].get<double>(),
      1e4 * figures["mesh"]["reference_area_m2"].get<double>());
  for (const nlohmann::json& surface : figures["proxy_surfaces"]) {
    text += fmt::format(
        "  proxy-{:.1f}: the proxy's own surface (its voxels' boundary, {} Taubin pairs, moved {} "
        "voxel in): {} pieces, area {:.2f}x the reference's\n",
        surface["inward_voxels"].get<double>(), surface["smoothing_iterations"].get<int>(),
        surface["inward_voxels"].get<double>(), surface["pieces"].get<int>(),
        surface["area_ratio"].get<double>());
  }
  text += fmt::format(
      "  height {:.1f} mm (reference {:.1f}, {:+.1f} %), width {:.1f} mm (reference {:.1f}, "
      "{:+.1f} %)\n",
      1e3 * t["height_m"].get<double>(), 1e3 * t["reference_height_m"].get<double>(),
      100 * (t["height_m"].get<double>() / t["reference_height_m"].get<double>() - 1),
      1e3 * t["width_m"].get<double>(), 1e3 * t["reference_width_m"].get<double>(),
      100 * (t["width_m"].get<double>() / t["reference_width_m"].get<double>() - 1));
  text += fmt::format(
      "  masks ({} views, within {} px of the reference's silhouette): plant {:.2f} % of the "
      "image (median); mask pixels off the reference {:.1f} % median, {:.1f} % worst; reference "
      "covered {:.1f} % median, {:.1f} % worst\n",
      masks["views"].size(), masks["tolerance_px"].get<double>(),
      100 * masks["plant_fraction_median"].get<double>(),
      100 * masks["off_reference_median"].get<double>(),
      100 * masks["off_reference_max"].get<double>(),
      100 * masks["reference_covered_median"].get<double>(),
      100 * masks["reference_covered_min"].get<double>());
  return text;
}

}  // namespace avc::bench
