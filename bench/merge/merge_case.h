#pragma once

// One row of `avc bench merge`: a simulated scan's plant proxy (carved by the builder from the
// scan's automatic masks), a raw cloud with injected outliers, and model merging (paper §3.1)
// into the proxy's voxels, both clouds scored against the plant's ground truth.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace avc::bench {

enum class RawSource {
  kSimulated,  // ground-truth samples with Gaussian noise (simulated_mvs_cloud.h)
  kPatchMvs,   // the builder's patch MVS on the scan's images
};

struct MergeCase {
  std::string dataset_name;
  std::filesystem::path scan;
  RawSource source = RawSource::kSimulated;
  double outlier_fraction = 0.05;
  uint64_t seed = 1;
  int merge_repeats = 5;  // timed merges; the median is reported
  double voxel_size = 0;  // final proxy voxel, metres; 0 = the builder's automatic one
};

// Figures: voxel_size_m, raw_points, injected_outliers, merged_points, removed_points
// (outside_proxy + in_sparse_voxels: in occupied voxels with too few points), raw_rmse_m /
// raw_mean_m, merged_rmse_m / merged_mean_m (distances to the plant's organs), rmse_ratio (raw /
// merged), merge_seconds (median).
nlohmann::json RunMergeCase(const MergeCase& merge_case);

}  // namespace avc::bench
