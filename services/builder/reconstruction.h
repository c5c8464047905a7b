#pragma once

// The builder's work on a set of calibrated images (paper §2.2–3): lens distortion removed,
// plant masks (given or automatic), the plant proxy carved from them coarse to fine, then
// multi-view stereo bounded by the proxy. Used offline by `avc reconstruct` and `avc bench mvs`,
// and live by the builder node.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/dataset/view.h"
#include "core/merge/merge_points.h"
#include "core/mvs/mvs_points.h"
#include "core/mvs/patch/patch_mvs.h"
#include "core/mvs/plane_sweep/plane_sweep_mvs.h"
#include "core/ppr/plant_proxy.h"
#include "core/segmentation/fill_masks.h"
#include "services/builder/soil_level.h"
#include "services/builder/support_level.h"

namespace avc::builder {

enum class MvsMethod { kPatch, kPlaneSweep, kNone };

// "patch", "plane-sweep", "none"; parsing throws std::invalid_argument listing the choices.
std::string MvsMethodName(MvsMethod method);
MvsMethod ParseMvsMethod(const std::string& name);

struct ReconstructOptions {
  segmentation::MaskOptions masks;
  ppr::ProxyOptions proxy;
  MvsMethod method = MvsMethod::kPatch;
  mvs::PatchMvsOptions patch;
  mvs::PlaneSweepOptions sweep;
  SoilLevelOptions soil;
  SupportOptions support;
  // MVS points farther than this many voxels from the proxy's occupied voxels are removed from
  // points.ply (merging drops every point outside them either way); negative keeps them all.
  // Higher keeps more of what patch expansion reaches past the proxy: more recall, less
  // precision (BENCHMARKS.md, "Where the defaults come from").
  int points_proxy_margin = 0;

  // Empty when usable; else the first bad setting (of the MVS, soil and support options).
  std::string Validate() const;
};

struct StageTime {
  std::string stage;  // "undistort", "masks", "proxy", "soil", "mvs", "merge"
  double seconds = 0;
};

struct Reconstruction {
  ppr::PlantProxy proxy;
  mvs::MvsPoints points;              // empty when the method is kNone
  uint64_t points_outside_proxy = 0;  // MVS points removed for lying outside the proxy
  // The points merged into the proxy's voxels (paper §3.1): one per voxel holding more than 3.
  merge::MergedPoints merged;
  segmentation::MaskSummary masks;
  std::vector<StageTime> timings;  // wall clock, for reports only (never in the products)
  // The soil surface under the plant, where its height is measured from (soil_level.h).
  std::optional<SoilLevel> soil;
  std::string soil_not_found;  // why, when soil is empty
  // What the plant stands on when the masks took it for plant; the proxy and masks are cut at
  // its top (support_level.h).
  std::optional<SupportTop> support;
};

// stage: what is running; done/total: its progress.
using ReconstructProgress =
    std::function<void(const std::string& stage, size_t done, size_t total)>;

// Changes `set` in place (undistorted images, masks filled). Throws std::invalid_argument or
// std::runtime_error naming the view or setting at fault (no views, a bad camera, no plant
// found in any image, ...).
Reconstruction Reconstruct(dataset::ViewSet& set, const ReconstructOptions& options,
                           const ReconstructProgress& progress = {});

}  // namespace avc::builder
