#pragma once

// What a reconstruction run reports (the paper's Table 1 per run): images, points, points per
// image and, when the ground truth is known (simulated scans), the points' distance to it and
// precision / recall; plus the proxy's size, the masks and the time per stage.

#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "core/eval/metrics.h"
#include "services/builder/reconstruction.h"

namespace avc::builder {

struct BuildReport {
  std::string method;
  size_t images = 0;
  size_t points = 0;
  double points_per_image = 0;
  // Merging into the proxy's voxels: points kept, and MVS points dropped as outliers (outside
  // the occupied voxels, removed from points.ply unless kept, or in voxels holding too few).
  size_t merged_points = 0;
  uint64_t outliers_outside_proxy = 0;
  uint64_t outliers_in_sparse_voxels = 0;
  double voxel_size = 0;
  ppr::VoxelCounts voxels;
  std::vector<StageTime> timings;
  double peak_memory_mb = 0;  // of this process so far
  segmentation::MaskSummary masks;
  std::optional<SoilLevel> soil;      // where the plant's height is measured from, when found
  std::string soil_not_found;         // why there is no soil level
  std::optional<SupportTop> support;  // what the proxy was cut at, when found
  // Present when a ground-truth mesh was given.
  std::optional<eval::EvalResult> accuracy;
};

// Evaluates against `ground_truth_mesh` when it is not empty (throws naming the file if it
// cannot be read); its coordinates are taken to the views' world by `ground_truth_to_world`
// (ViewSet::FileToWorld(): the dataset's unit and upright turn).
BuildReport MakeBuildReport(const Reconstruction& reconstruction, MvsMethod method,
                            const std::filesystem::path& ground_truth_mesh,
                            const Eigen::Matrix3d& ground_truth_to_world);

// A mask at least this much plant does not tell the plant from its background.
inline constexpr double kMostlyPlantFraction = 0.9;

// The names of the views whose mask's plant fraction passes `test`.
std::vector<std::string> MaskViewsWhere(const segmentation::MaskSummary& masks,
                                        const std::function<bool(double)>& test);
// ... that show no plant; that are at least kMostlyPlantFraction plant.
std::vector<std::string> MasksWithoutPlant(const segmentation::MaskSummary& masks);
std::vector<std::string> MasksMostlyPlant(const segmentation::MaskSummary& masks);
// Warnings (one line each) for masks with no plant and masks almost all plant; empty if none.
std::string DescribeMaskProblems(const segmentation::MaskSummary& masks);

nlohmann::ordered_json BuildReportToJson(const BuildReport& report);
// A few lines for a terminal.
std::string BuildReportToText(const BuildReport& report);

}  // namespace avc::builder
