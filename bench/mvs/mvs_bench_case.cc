#include "bench/mvs/mvs_bench_case.h"

#include <chrono>

#include "bench/mvs/plant_organs.h"
#include "core/dataset/dataset_reader.h"
#include "core/eval/metrics.h"
#include "core/eval/silhouette_agreement.h"
#include "core/geometry/mesh_io.h"
#include "core/segmentation/threshold_silhouette.h"

namespace avc::bench {

nlohmann::json RunMvsCase(const MvsCase& mvs_case) {
  dataset::ViewSet set = dataset::ReadDataset(mvs_case.dataset);
  builder::ReconstructOptions options;
  options.method = mvs_case.method;
  options.patch.level = mvs_case.level;
  options.sweep.level = mvs_case.level;
  const auto start = std::chrono::steady_clock::now();
  const builder::Reconstruction reconstruction = builder::Reconstruct(set, options);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  double mvs_seconds = 0;
  for (const builder::StageTime& t : reconstruction.timings) {
    if (t.stage == "mvs") mvs_seconds = t.seconds;
  }
  const mvs::MvsPoints& points = reconstruction.points;
  nlohmann::json result = {
      {"points", points.size()},
      {"images", set.views.size()},
      {"points_per_image", static_cast<double>(points.size()) / set.views.size()},
      {"seconds", seconds},
      {"mvs_seconds", mvs_seconds},
      {"voxel_size_m", reconstruction.proxy.voxel_size()}};
  if (mvs_case.silhouettes) {
    std::vector<cv::Mat> silhouettes;
    for (const dataset::View& view : set.views) {
      silhouettes.push_back(segmentation::ThresholdSilhouette(view.image, 0.19, 10, 7));
    }
    result["inside_fraction"] = eval::InsideAllSilhouettesFraction(points, set.views, silhouettes);
  }
  if (!set.ground_truth_mesh.empty() && points.size() > 0) {
    const geometry::Mesh truth = PlantOrgans(geometry::ReadMesh(set.ground_truth_mesh));
    eval::EvalOptions eval_options;
    eval_options.thresholds = {0.001, 0.002};
    const eval::EvalResult scores = eval::EvaluatePointCloud(truth, points.cloud, eval_options);
    result["precision_1mm"] = scores.scores[0].precision;
    result["recall_2mm"] = scores.scores[1].recall;
    result["mean_distance_m"] = scores.accuracy.mean;
  }
  return result;
}

}  // namespace avc::bench
