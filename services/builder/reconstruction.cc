#include "services/builder/reconstruction.h"

#include <fmt/format.h>

#include <chrono>
#include <opencv2/core.hpp>
#include <stdexcept>

#include "core/dataset/view_transforms.h"
#include "core/ppr/proxy_bounds.h"

namespace avc::builder {
namespace {

class StageClock {
 public:
  explicit StageClock(std::vector<StageTime>* timings) : timings_(timings) {}
  void Finish(const std::string& stage) {
    const auto now = std::chrono::steady_clock::now();
    timings_->push_back({stage, std::chrono::duration<double>(now - start_).count()});
    start_ = now;
  }

 private:
  std::vector<StageTime>* timings_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace

std::string MvsMethodName(MvsMethod method) {
  switch (method) {
    case MvsMethod::kPatch:
      return "patch";
    case MvsMethod::kPlaneSweep:
      return "plane-sweep";
    case MvsMethod::kNone:
      break;
  }
  return "none";
}

MvsMethod ParseMvsMethod(const std::string& name) {
  for (MvsMethod method : {MvsMethod::kPatch, MvsMethod::kPlaneSweep, MvsMethod::kNone}) {
    if (name == MvsMethodName(method)) return method;
  }
  throw std::invalid_argument("unknown MVS method '" + name +
                              "' (choose patch, plane-sweep or none)");
}

Reconstruction Reconstruct(dataset::ViewSet& set, const ReconstructOptions& options,
                           const ReconstructProgress& progress) {
  if (set.views.empty()) throw std::invalid_argument("the dataset has no views");
  const auto report = [&](const std::string& stage, size_t done, size_t total) {
    if (progress) progress(stage, done, total);
  };
  std::vector<StageTime> timings;
  StageClock clock(&timings);

  for (size_t i = 0; i < set.views.size(); ++i) {
    dataset::Undistort(set.views[i]);
    report("undistort", i + 1, set.views.size());
  }
  clock.Finish("undistort");

  report("masks", 0, set.views.size());
  segmentation::MaskSummary masks = segmentation::FillMissingMasks(set, options.masks);
  report("masks", set.views.size(), set.views.size());
  size_t views_with_plant = 0;
  for (const dataset::View& view : set.views) views_with_plant += cv::countNonZero(view.mask) > 0;
  if (views_with_plant == 0) {
    throw std::runtime_error(
        "no plant found in any image (automatic masks are empty); check the images or give "
        "masks in masks/<image name>");
  }
  clock.Finish("masks");

  const Eigen::AlignedBox3d box = ppr::BoundsFromViews(set.views);
  ppr::PlantProxy proxy(box, options.proxy);
  for (size_t i = 0; i < set.views.size(); ++i) {
    proxy.AddView(set.views[i]);
    report("proxy", i + 1, set.views.size());
  }
  for (int i = 0; i < options.proxy.resolution_increases; ++i) proxy.IncreaseResolution();
  if (proxy.Counts().occupied == 0) {
    throw std::runtime_error(fmt::format(
        "the plant proxy is empty: no voxel is inside the plant masks of at least {} views; the "
        "masks or the cameras disagree",
        options.proxy.min_plant_views));
  }
  clock.Finish("proxy");

  report("soil", 0, 1);
  std::optional<SoilLevel> soil = FindSoilLevel(set.views, proxy.ToMvsBounds(), options.soil);
  report("soil", 1, 1);
  clock.Finish("soil");

  mvs::MvsPoints points;
  const auto mvs_progress = [&](const std::string& stage, size_t done, size_t total) {
    report("mvs " + stage, done, total);
  };
  if (options.method == MvsMethod::kPatch) {
    points = mvs::RunPatchMvs(set.views, proxy.ToMvsBounds(), options.patch, mvs_progress);
  } else if (options.method == MvsMethod::kPlaneSweep) {
    points = mvs::RunPlaneSweep(set.views, proxy.ToMvsBounds(), options.sweep, mvs_progress);
  }
  clock.Finish("mvs");
  merge::MergedPoints merged;
  if (points.size() > 0) merged = merge::MergeIntoProxy(points, proxy.ToMvsBounds());
  clock.Finish("merge");
  return {std::move(proxy), std::move(points),  std::move(merged),
          std::move(masks), std::move(timings), soil};
}

}  // namespace avc::builder
