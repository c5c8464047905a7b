#include "bench/merge/merge_case.h"

#include <algorithm>
#include <chrono>
#include <vector>

#include "bench/merge/simulated_mvs_cloud.h"
#include "bench/mvs/plant_organs.h"
#include "bench/summary.h"
#include "core/dataset/dataset_reader.h"
#include "core/eval/metrics.h"
#include "core/geometry/mesh_io.h"
#include "core/merge/merge_points.h"
#include "services/builder/reconstruction.h"

namespace avc::bench {
namespace {

// Outliers land within 1 cm of the plant, like MVS mismatches (and the Table 2 sets' outliers).
Eigen::AlignedBox3d GrownBounds(const geometry::Mesh& mesh, double margin) {
  Eigen::Vector3f min, max;
  geometry::Bounds(mesh, &min, &max);
  const Eigen::Vector3d grow = Eigen::Vector3d::Constant(margin);
  return {min.cast<double>() - grow, max.cast<double>() + grow};
}

eval::DistanceStats Accuracy(const geometry::Mesh& truth, const geometry::PointCloud& cloud) {
  eval::EvalOptions options;
  options.thresholds = {0.001};
  return eval::EvaluatePointCloud(truth, cloud, options).accuracy;
}

}  // namespace

nlohmann::json RunMergeCase(const MergeCase& merge_case) {
  dataset::ViewSet set = dataset::ReadDataset(merge_case.scan);
  if (set.ground_truth_mesh.empty()) {
    throw std::runtime_error(merge_case.scan.string() + " has no ground-truth mesh");
  }
  const geometry::Mesh truth = PlantOrgans(geometry::ReadMesh(set.ground_truth_mesh));
  builder::ReconstructOptions options;
  options.method = merge_case.source == RawSource::kPatchMvs ? builder::MvsMethod::kPatch
                                                             : builder::MvsMethod::kNone;
  options.proxy.final_voxel_size = merge_case.voxel_size;
  builder::Reconstruction reconstruction = builder::Reconstruct(set, options);

  mvs::MvsPoints raw = merge_case.source == RawSource::kPatchMvs
                           ? std::move(reconstruction.points)
                           : SimulatedMvsCloud(truth, {.seed = merge_case.seed});
  const size_t injected =
      InjectOutliers(raw, merge_case.outlier_fraction, GrownBounds(truth, 0.01), merge_case.seed);

  merge::MergedPoints merged;
  std::vector<double> merge_times;
  for (int r = 0; r < std::max(1, merge_case.merge_repeats); ++r) {
    const auto start = std::chrono::steady_clock::now();
    merged = merge::MergeIntoProxy(raw, reconstruction.proxy.ToMvsBounds());
    merge_times.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  const eval::DistanceStats raw_accuracy = Accuracy(truth, raw.cloud);
  const eval::DistanceStats merged_accuracy = Accuracy(truth, merged.cloud);
  return {{"voxel_size_m", merged.voxel_size},
          {"raw_points", raw.size()},
          {"injected_outliers", injected},
          {"merged_points", merged.size()},
          {"removed_points", merged.outside_proxy + merged.in_sparse_voxels},
          {"outside_proxy", merged.outside_proxy},
          {"in_sparse_voxels", merged.in_sparse_voxels},
          {"raw_rmse_m", raw_accuracy.rmse},
          {"raw_mean_m", raw_accuracy.mean},
          {"merged_rmse_m", merged_accuracy.rmse},
          {"merged_mean_m", merged_accuracy.mean},
          {"rmse_ratio", raw_accuracy.rmse / merged_accuracy.rmse},
          {"merge_seconds", Summarize(merge_times).median}};
}

}  // namespace avc::bench
