#include "bench/surface/scan_surface_case.h"

#include <chrono>
#include <nlohmann/json.hpp>

#include "bench/mvs/isolated_run.h"
#include "bench/mvs/plant_organs.h"
#include "bench/surface/leaf_connectivity.h"
#include "core/dataset/dataset_reader.h"
#include "core/eval/leaf_figures.h"
#include "core/eval/metrics.h"
#include "core/eval/report_json.h"
#include "core/geometry/mesh_io.h"
#include "core/surface/surface_images_io.h"
#include "services/builder/reconstruction.h"
#include "services/clusterer/merge_and_cluster.h"
#include "services/surfacer/plant_base.h"
#include "services/surfacer/surface_clusters.h"

namespace avc::bench {
namespace {

nlohmann::json SurfaceAndScore(const messages::ClustersContent& clusters,
                               const surface::SurfaceImages* images,
                               const surfacer::SurfacerOptions& options,
                               const geometry::Mesh& truth, const TruthTraits& expected) {
  const auto start = std::chrono::steady_clock::now();
  const surfacer::SurfacerResult surface = surfacer::SurfaceClusters(clusters, options, images);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!surface.problem.empty()) throw std::runtime_error(surface.problem);
  eval::EvalOptions evaluation;
  evaluation.thresholds = {0.002};  // precision and recall at 2 mm, as `avc bench e2e`
  nlohmann::json figures =
      eval::LeafFigures(eval::ToJson(eval::EvaluateMesh(truth, surface.mesh, evaluation)));
  // The traits as a scan reports them, against the same measures of the truth.
  figures["total_area_ratio"] = surface.traits.total_area / expected.leaf_area;
  figures["height_ratio"] = surface.traits.height / expected.height;
  // Faces go to the nearest organ (the mesh covers stems and petioles too); leaves are counted.
  const LeafConnectivity leaves = CountConnectedLeaves(truth, surface.mesh, true);
  figures["leaves"] = leaves.leaves;
  figures["connected_leaves"] = leaves.one_component;
  figures["mostly_one_leaves"] = leaves.mostly_one;
  figures["faces"] = surface.mesh.faces.size();
  figures["seconds"] = seconds;
  return figures;
}

nlohmann::json RunInChild(const std::filesystem::path& scan,
                          const surface::ImageGrowthOptions& growth) {
  dataset::ViewSet set = dataset::ReadDataset(scan);
  const builder::Reconstruction reconstruction = builder::Reconstruct(set, {});
  const messages::ClustersContent clusters = clusterer::ClusterMerged(
      reconstruction.merged, static_cast<int64_t>(reconstruction.points.size()), {}, "points",
      "ppr");
  if (!clusters.problem.empty()) throw std::runtime_error(clusters.problem);
  const geometry::Mesh ground_truth = geometry::ReadMesh(set.ground_truth_mesh);
  const geometry::Mesh truth = PlantOrgans(ground_truth);
  const TruthTraits expected = MeasureTruthTraits(ground_truth);
  const surface::SurfaceImages images = surface::SurfaceImagesOf(set);
  surfacer::SurfacerOptions options;  // height as a scan measures it
  options.traits.ground_z = surfacer::PlantGroundZ(builder::SoilZ(reconstruction.soil),
                                                   reconstruction.proxy.ToMvsBounds());
  options.surface.image_growth = growth;
  return {{"images", set.views.size()},
          {"ground_error_m", *options.traits.ground_z - expected.ground_z},
          {"soil_found", reconstruction.soil.has_value()},
          {"merged_points", clusters.merged.cloud.size()},
          {"band", SurfaceAndScore(clusters, nullptr, options, truth, expected)},
          {"images_growth", SurfaceAndScore(clusters, &images, options, truth, expected)}};
}

}  // namespace

std::vector<ScanSurfaceRow> RunScanSurfaceCase(const std::string& preset,
                                               const std::filesystem::path& scan,
                                               const surface::ImageGrowthOptions& growth) {
  const IsolatedResult run = RunIsolated([&] { return RunInChild(scan, growth); });
  std::vector<ScanSurfaceRow> rows;
  for (const auto& [key, method] : {std::pair{"band", "band growth (no images)"},
                                    std::pair{"images_growth", "image level sets"}}) {
    ScanSurfaceRow row;
    row.preset = preset;
    row.method = method;
    row.ok = run.ok;
    row.error = run.error;
    if (run.ok) {
      const nlohmann::json& figures = run.result[key];
      row.images = run.result["images"].get<size_t>();
      row.merged_points = run.result["merged_points"].get<size_t>();
      row.ground_error = run.result["ground_error_m"].get<double>();
      row.soil_found = run.result["soil_found"].get<bool>();
      row.leaf_area_ratio = figures["area_ratio"].get<double>();
      row.accuracy_mean = 1e-3 * figures["accuracy_mean_mm"].get<double>();
      row.precision_2mm = figures["precision_2mm"].get<double>();
      row.recall_2mm = figures["recall_2mm"].get<double>();
      row.total_area_ratio = figures["total_area_ratio"].get<double>();
      row.height_ratio = figures["height_ratio"].get<double>();
      row.leaves = figures["leaves"].get<int>();
      row.connected_leaves = figures["connected_leaves"].get<int>();
      row.mostly_one_leaves = figures["mostly_one_leaves"].get<int>();
      row.faces = figures["faces"].get<size_t>();
      row.seconds = figures["seconds"].get<double>();
    }
    rows.push_back(row);
  }
  return rows;
}

}  // namespace avc::bench
