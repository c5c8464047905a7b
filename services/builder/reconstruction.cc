#include "services/builder/reconstruction.h"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <opencv2/core.hpp>
#include <stdexcept>

#include "core/dataset/view_transforms.h"
#include "core/dataset/world_up.h"
#include "core/mvs/depth_range.h"
#include "core/ppr/proxy_bounds.h"
#include "core/util/validation.h"

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

ppr::PlantProxy CarveProxy(const std::vector<dataset::View>& views, const Eigen::AlignedBox3d& box,
                           const ppr::ProxyOptions& options,
                           const std::function<void(const std::string&, size_t, size_t)>& report) {
  ppr::PlantProxy proxy(box, options);
  for (size_t i = 0; i < views.size(); ++i) {
    proxy.AddView(views[i]);
    report("proxy", i + 1, views.size());
  }
  return proxy;
}

// The views whose mask shows plant (sharing their pixels and masks). A view with none says
// nothing about where the plant is, would carve it away wherever it looks, and has nothing for
// MVS to match: it is left out (the build report names it).
struct ViewsInUse {
  std::vector<dataset::View> views;
  std::vector<uint32_t> set_index;  // of each, in the set
};

ViewsInUse ViewsWithPlant(const std::vector<dataset::View>& views) {
  ViewsInUse in_use;
  for (size_t i = 0; i < views.size(); ++i) {
    if (cv::countNonZero(views[i].mask) == 0) continue;
    in_use.views.push_back(views[i]);
    in_use.set_index.push_back(static_cast<uint32_t>(i));
  }
  return in_use;
}

// MVS points name the views they were given; the products name the set's views.
void RenumberViews(mvs::MvsPoints& points, const std::vector<uint32_t>& set_index) {
  for (std::vector<uint32_t>& views : points.views) {
    for (uint32_t& view : views) view = set_index[view];
  }
}

// True when most computed masks separate the plant by its distance from the backdrop's colour,
// which keeps a pale stage, block or pot as well; excess-green masks leave them out already, and
// given masks are trusted.
bool MasksKeepTheSupport(const segmentation::MaskSummary& masks) {
  int by_distance = 0;
  for (const segmentation::ViewMask& view : masks.views) {
    by_distance += !view.given && view.method == segmentation::MaskMethod::kBackgroundDistance;
  }
  return 2 * by_distance > static_cast<int>(masks.views.size());
}

// A support lies below the plant: only where the views agree that z is up.
bool CamerasAgreeZIsUp(const std::vector<dataset::View>& views) {
  std::vector<camera::Camera> cameras;
  for (const dataset::View& view : views) cameras.push_back(view.camera);
  return dataset::CamerasAgreeZIsUp(cameras);
}

// A support in `proxy` whose top lies inside the box: raises the box's floor to it.
std::optional<SupportTop> CutAtSupport(const SupportOptions& options, Eigen::AlignedBox3d& box,
                                       const ppr::PlantProxy& proxy) {
  std::optional<SupportTop> support =
      FindSupportTop(proxy.OccupiedCentres(), proxy.voxel_size(), options);
  if (!support || support->z <= box.min().z() + 0.5 * proxy.voxel_size() ||
      support->z >= box.max().z()) {
    return std::nullopt;
  }
  box.min().z() = support->z;
  return support;
}

// Removes from every mask what no occupied voxel projects to (the support the proxy was cut
// at), and updates the masks' plant fractions.
void CutMasksToProxy(dataset::ViewSet& set, const mvs::MvsBounds& proxy,
                     segmentation::MaskSummary& summary) {
  tbb::parallel_for(size_t{0}, set.views.size(), [&](size_t i) {
    dataset::View& view = set.views[i];
    view.mask &= mvs::ComputeDepthRange(view.camera, proxy, 0).far_depth > 0;
    summary.views[i].plant_fraction =
        static_cast<double>(cv::countNonZero(view.mask)) / static_cast<double>(view.mask.total());
  });
}

// The plant proxy from the views whose masks show plant, cut at the top of a support the masks
// took for plant (the masks are then cut to the proxy too); its views released, since its
// resolution is final. Throws std::runtime_error when no voxel survives.
struct CarvedProxy {
  ppr::PlantProxy proxy;
  std::optional<SupportTop> support;
};

CarvedProxy CarvePlantProxy(dataset::ViewSet& set, const ReconstructOptions& options,
                            segmentation::MaskSummary& masks,
                            const std::function<void(const std::string&, size_t, size_t)>& report) {
  const ViewsInUse in_use = ViewsWithPlant(set.views);
  const std::vector<dataset::View>& carving = in_use.views;
  Eigen::AlignedBox3d box = ppr::BoundsFromViews(carving);
  ppr::ProxyOptions proxy_options = options.proxy;
  ppr::PlantProxy proxy = CarveProxy(carving, box, proxy_options, report);
  // Masks that keep everything unlike the backdrop (not the green of foliage) keep what the plant
  // stands on too. The proxy's first level shows it: cut the box at its top and carve again,
  // with the voxels the whole box would have had; then once more on the final voxels, which
  // place the top to a voxel.
  std::optional<SupportTop> support;
  if (MasksKeepTheSupport(masks) && CamerasAgreeZIsUp(set.views)) {
    support = CutAtSupport(options.support, box, proxy);
  }
  if (support && proxy_options.final_voxel_size == 0) {
    proxy_options.final_voxel_size =
        proxy.voxel_size() / static_cast<double>(1 << options.proxy.resolution_increases);
  }
  if (support) proxy = CarveProxy(carving, box, proxy_options, report);
  for (int i = 0; i < options.proxy.resolution_increases; ++i) proxy.IncreaseResolution();
  if (support) {
    if (auto finer = CutAtSupport(options.support, box, proxy)) {
      support = finer;
      proxy = CarveProxy(carving, box, proxy_options, report);
      for (int i = 0; i < options.proxy.resolution_increases; ++i) proxy.IncreaseResolution();
    }
  }
  if (proxy.Counts().occupied == 0) {
    throw std::runtime_error(fmt::format(
        "the plant proxy is empty: no voxel is inside the plant masks of at least {} views; the "
        "masks or the cameras disagree",
        options.proxy.min_plant_views));
  }
  proxy.ReleaseViews();
  if (support) CutMasksToProxy(set, proxy.ToMvsBounds(), masks);
  return {std::move(proxy), support};
}

}  // namespace

std::string ReconstructOptions::Validate() const {
  FirstProblem problem;
  problem.Include(patch.Validate());
  problem.Include(sweep.Validate());
  problem.Include(soil.Validate());
  problem.Include(support.Validate());
  return problem.text();
}

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

  auto [proxy, support] = CarvePlantProxy(set, options, masks, report);
  const mvs::MvsBounds bounds = proxy.ToMvsBounds();
  clock.Finish("proxy");

  report("soil", 0, 1);
  // On a support the plant's base is its top; the soil search assumes masks that leave the pot
  // and soil out, which these did not.
  std::optional<SoilLevel> soil;
  std::string soil_not_found = "not searched on a support";
  if (!support) {
    soil = FindSoilLevel(set.views, bounds, options.soil, &soil_not_found);
  }
  report("soil", 1, 1);
  clock.Finish("soil");

  mvs::MvsPoints points;
  const auto mvs_progress = [&](const std::string& stage, size_t done, size_t total) {
    report("mvs " + stage, done, total);
  };
  // Again after the masks were cut to the proxy, which can leave a view without plant.
  const ViewsInUse matching = ViewsWithPlant(set.views);
  if (options.method == MvsMethod::kPatch) {
    points = mvs::RunPatchMvs(matching.views, bounds, options.patch, mvs_progress);
  } else if (options.method == MvsMethod::kPlaneSweep) {
    points = mvs::RunPlaneSweep(matching.views, bounds, options.sweep, mvs_progress);
  }
  RenumberViews(points, matching.set_index);
  uint64_t outside_proxy = 0;
  if (options.points_proxy_margin >= 0 && points.size() > 0) {
    points = merge::PointsInProxy(points, bounds, options.points_proxy_margin, &outside_proxy);
  }
  clock.Finish("mvs");
  merge::MergedPoints merged;
  if (points.size() > 0) merged = merge::MergeIntoProxy(points, bounds);
  clock.Finish("merge");
  return {
      std::move(proxy), std::move(points),  outside_proxy, std::move(merged),
      std::move(masks), std::move(timings), soil,          soil ? std::string() : soil_not_found,
      support};
}

}  // namespace avc::builder
