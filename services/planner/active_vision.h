#pragma once

// The paper's active vision (Gibbs et al. §2.2, Algorithm 1), with no LCM: the planner decides
// where the camera goes and a Capture function takes the picture (the live cell through the
// drivers, or the simulated cell in tests and benchmarks) and returns its plant mask.
//  - Framing (line 4): at each of three heights a live-view frame is masked and the distance and
//    aim adjusted until the plant fills frame_fill of the field of view (within frame_tolerance).
//  - Phase 1 (lines 5-12): ten views per height around the plant, offset by 12 degrees between
//    heights; the plant proxy is created from the first height's views and updated per height.
//  - Phase 2 (lines 13-23): the proxy's surface is clustered into patches (proxy_patches.h) and
//    scored (patch_visibility.h). For each failing patch the incremental view sphere is searched:
//    the view along the patch normal first, then rings of sphere_step around it, until a view is
//    reachable (cell_view.h) and sees the patch; of that ring's acceptable views the one seeing
//    the most failing patches is captured, the proxy updated and the patches re-scored. Rounds
//    repeat until every patch passes, no failing patch has a view left, or max_views is spent.
//  - Phase 3 (lines 24-25): images whose removal leaves every patch that passes with all images
//    passing are removed, least useful first (redundant_views.h); then the resolution is
//    raised.
// Deterministic for a deterministic Capture: no clock or randomness inside the decisions.

#include <Eigen/Geometry>
#include <functional>
#include <opencv2/core/mat.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/ppr/plant_proxy.h"
#include "services/planner/cell_view.h"
#include "services/planner/patch_visibility.h"
#include "services/planner/proxy_patches.h"

namespace avc::planner {

// Takes the picture at `view` and returns its plant mask (CV_8UC1, non-zero = plant, the
// camera's size), or nullopt when the capture failed (the view is skipped).
using CaptureFunction = std::function<std::optional<cv::Mat>(const CellView& view)>;

struct ActiveVisionOptions {
  int levels = 3;
  int views_per_level = 10;
  double level_offset_deg = 12;  // turntable offset between heights (Algorithm 1 line 5)
  std::vector<double> elevations_deg = {15, 35, 55};
  // Framing: the plant's masked extent over the image's, wanted and allowed deviation.
  double frame_fill = 0.75;
  double frame_tolerance = 0.1;
  int frame_iterations = 4;
  double start_distance = 0.6;     // first framing frame, metres from the aim
  double start_aim_height = 0.12;  // first aim above the turntable, metres
  int max_views = 40;              // Phase 1 and Phase 2 together
  double sphere_step_deg = 10;     // incremental view sphere: ring spacing
  int sphere_rings = 9;            // up to 90 degrees from the patch normal
  // Among the first acceptable ring's candidates, take the one that sees the most failing
  // patches (false: the first acceptable, as the paper).
  bool rank_candidates = true;
  bool remove_redundant = true;
  // Phase 3 also keeps every failing patch at its score with all images. Off (the paper's rule):
  // only passing patches hold views back. On keeps more images for little or no gain in
  // coverage (BENCHMARKS.md, "Where the defaults come from").
  bool prune_holds_failing_scores = false;
  // Phase 3's order counts how useful a view is on the patches' sampled faces (the last needed
  // view of how many), not on whole patches: as few or fewer images for as much or more
  // coverage on the simulated plants (BENCHMARKS.md, "Where the defaults come from").
  bool prune_order_by_faces = true;
  // With prune_order_by_faces: the fraction of the faces covered with all images that Phase 3
  // may leave with fewer than min_views views (1: the paper's rule alone).
  double prune_max_covered_faces_lost = 1.0;
  ppr::ProxyOptions proxy;
  PatchOptions patches;
  VisibilityOptions visibility;
  ReachOptions reach;
};

struct PlannedView {
  CellView view;
  std::string phase;   // "initial" or "active"
  std::string reason;  // why it was chosen
  int patch = -1;      // active: the patch it was chosen for
  double patch_score = 0;
  bool kept = true;  // false: removed as redundant in Phase 3
};

struct ActiveVisionResult {
  std::vector<PlannedView> views;    // in capture order
  std::vector<double> patch_scores;  // of the final patches with the kept views
  int patches = 0;
  int failing_patches = 0;                // below 1 at the end
  std::vector<double> iteration_seconds;  // planning time of each next-best-view search
  // Phase 2's planning (patches, scores, searches; not the captures) over its chosen views.
  double planning_seconds_per_view = 0;
  std::vector<std::string> notes;        // what could not be done, and why
  std::optional<ppr::PlantProxy> proxy;  // at the raised resolution, from the kept views
  // Phase 1's framing, for comparisons around the same plant: the aim of the last height and
  // the framed distance per height.
  Eigen::Vector3d aim = Eigen::Vector3d::Zero();
  std::vector<double> framed_distances;

  size_t KeptCount() const;
};

// The stages of a run, in order, for a caller that tracks them (the orchestrator's states):
// framing the first height, the first orbit view taken (later heights frame and orbit within
// this stage), the next-best-view rounds, redundant-view removal.
enum class ActiveVisionStage { kFrame, kInitialCapture, kActiveVision, kPruneViews };
using StageFunction = std::function<void(ActiveVisionStage stage)>;
// Hears the plant proxy each time it was created or carved by a new view (e.g. to keep the
// arm out of the plant's space).
using ProxyFunction = std::function<void(const ppr::PlantProxy& proxy)>;

// Throws std::runtime_error naming the problem when no plant is found by the colour filter in a
// framing frame or no view of the first height is reachable. `on_stage` (optional) hears each
// stage as it starts, `on_proxy` (optional) each proxy update.
ActiveVisionResult RunActiveVision(const cell::CellModel& cell, const CaptureFunction& capture,
                                   const ActiveVisionOptions& options = {},
                                   const StageFunction& on_stage = {},
                                   const ProxyFunction& on_proxy = {});

}  // namespace avc::planner
