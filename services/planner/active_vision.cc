#include "services/planner/active_vision.h"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <numeric>
#include <stdexcept>

#include "core/cell/view_selection.h"
#include "core/kinematics/plant_keep_out.h"
#include "core/ppr/proxy_bounds.h"
#include "services/planner/framing.h"
#include "services/planner/redundant_views.h"
#include "services/planner/view_sphere_search.h"

namespace avc::planner {
namespace {

constexpr double kDegree = M_PI / 180;

Eigen::Vector3d EyeAt(const Eigen::Vector3d& aim, double distance, double elevation,
                      double azimuth) {
  return aim + distance * Eigen::Vector3d(std::cos(elevation) * std::cos(azimuth),
                                          std::cos(elevation) * std::sin(azimuth),
                                          std::sin(elevation));
}

bool InImage(const camera::Camera& camera, const Eigen::Vector3d& point) {
  const auto pixel = camera.Project(point);
  const camera::Intrinsics& k = camera.intrinsics;
  return pixel && pixel->x() >= 0 && pixel->y() >= 0 && pixel->x() <= k.width - 1 &&
         pixel->y() <= k.height - 1;
}

// What Algorithm 1 keeps while it runs: the views with their masks, the proxy, the joints.
struct Run {
  const cell::CellModel& cell;
  const CaptureFunction& capture;
  const ActiveVisionOptions& options;
  ActiveVisionResult result;
  std::vector<cv::Mat> masks;  // per result.views entry
  kinematics::JointVector joints;
  std::vector<double> distances;  // Phase 1's per height
  std::function<void(ActiveVisionStage)> stage;
  const ProxyFunction& proxy_changed;
  ReachOptions reach;  // options.reach with the plant keep-out of the current proxy

  // The envelope's plant keep-out follows the proxy, as avc-robot's does during a scan.
  void ProxyChanged() {
    if (reach.envelope) {
      reach.envelope->plant_keep_out = kinematics::PlantKeepOutFromVoxels(
          result.proxy->OccupiedCentres(), result.proxy->voxel_size(), cell.T_base_table,
          reach.plant_keep_out_margin);
    }
    if (proxy_changed) proxy_changed(*result.proxy);
  }

  // Captures `view` and records it; false when the capture failed.
  bool Take(PlannedView planned) {
    std::optional<cv::Mat> mask = capture(planned.view);
    if (!mask) {
      result.notes.push_back(fmt::format("capture failed at turntable {:.1f} deg ({}); skipped",
                                         planned.view.turntable_angle / kDegree, planned.reason));
      return false;
    }
    if (result.views.empty()) stage(ActiveVisionStage::kInitialCapture);
    joints = planned.view.joints;
    if (result.proxy) {
      result.proxy->AddView(planned.view.camera, *mask);
      ProxyChanged();
    }
    masks.push_back(std::move(*mask));
    result.views.push_back(std::move(planned));
    return true;
  }

  void InitialLevel(int level) {
    const double elevation = options.elevations_deg[level] * kDegree;
    const double first_azimuth = level * options.level_offset_deg * kDegree;
    FramingRequest request;
    request.elevation = elevation;
    request.start_distance = options.start_distance;
    request.start_aim_height = options.start_aim_height;
    request.fill = options.frame_fill;
    request.tolerance = options.frame_tolerance;
    request.iterations = options.frame_iterations;
    const Framing framing = FramePlant(
        request,
        [&](double distance,
            const Eigen::Vector3d& aim) -> std::optional<std::pair<CellView, cv::Mat>> {
          const auto view = RealiseView(cell, EyeAt(aim, distance, elevation, first_azimuth), aim,
                                        {}, joints, reach);
          if (!view) return std::nullopt;
          auto mask = capture(*view);
          if (!mask) return std::nullopt;
          joints = view->joints;  // the arm went there for the frame
          return std::pair{*view, std::move(*mask)};
        });
    if (!framing.note.empty()) result.notes.push_back(framing.note);
    distances.push_back(framing.distance);
    result.aim = framing.aim;
    const Eigen::AlignedBox3d keep_out =
        result.proxy ? result.proxy->OccupiedBounds() : Eigen::AlignedBox3d();
    for (int n = 0; n < options.views_per_level; ++n) {
      const double azimuth = first_azimuth + 2 * M_PI * n / options.views_per_level;
      // Nearer when the arm cannot reach the framed distance there (the image then shows less
      // margin; the proxy tolerates a plant cut at the border only as unknown space).
      std::optional<CellView> view;
      for (double scale = 1.0; !view && scale > 0.6; scale -= 0.1) {
        view = RealiseView(cell, EyeAt(framing.aim, scale * framing.distance, elevation, azimuth),
                           framing.aim, keep_out, joints, reach);
      }
      if (!view) {
        result.notes.push_back(fmt::format(
            "height {} view {}: unreachable at elevation {:.0f} deg, azimuth {:.0f} deg; skipped",
            level + 1, n + 1, elevation / kDegree, azimuth / kDegree));
        continue;
      }
      Take({*view, "initial",
            fmt::format("height {} ({:.0f} deg), view {} of {}", level + 1, elevation / kDegree,
                        n + 1, options.views_per_level)});
    }
    if (!result.proxy) CreateProxy(level);
  }

  void CreateProxy(int level) {
    std::vector<camera::Camera> cameras;
    for (const PlannedView& v : result.views) cameras.push_back(v.view.camera);
    if (cameras.size() < 2) {
      throw std::runtime_error(
          fmt::format("height {}: {} views could be taken; the plant proxy needs at least 2",
                      level + 1, cameras.size()));
    }
    result.proxy.emplace(ppr::BoundsFromViews(cameras, masks), options.proxy);
    for (size_t i = 0; i < cameras.size(); ++i) result.proxy->AddView(cameras[i], masks[i]);
    ProxyChanged();
  }

  // `seen_by` (PatchesSeenBy or FacesSeenBy) for every view. Views in parallel: each is
  // independent, and the tree is built before (tree() is lazy).
  template <typename SeenBy>
  std::vector<PatchesSeen> EveryView(const std::vector<SurfacePatch>& patches,
                                     SeenBy&& seen_by) const {
    std::vector<PatchesSeen> seen(result.views.size());
    result.proxy->tree();
    tbb::parallel_for(size_t{0}, seen.size(), [&](size_t v) {
      seen[v] = seen_by(*result.proxy, patches, result.views[v].view.camera, options.visibility);
    });
    return seen;
  }

  std::vector<PatchesSeen> SeenByEveryView(const std::vector<SurfacePatch>& patches) const {
    return EveryView(patches, PatchesSeenBy);
  }

  void ActiveVision() {
    SphereSearch search;
    search.radius = std::accumulate(distances.begin(), distances.end(), 0.0) / distances.size();
    search.ring_step = options.sphere_step_deg * kDegree;
    search.rings = options.sphere_rings;
    // Wall clock for the report only: planning, not capturing (no decision depends on it).
    double planning = 0;
    int chosen = 0;
    while (static_cast<int>(result.views.size()) < options.max_views) {
      auto round_start = std::chrono::steady_clock::now();
      const std::vector<SurfacePatch> patches = ProxySurfacePatches(*result.proxy, options.patches);
      PatchViewCounts counts;
      for (const PatchesSeen& seen : SeenByEveryView(patches)) AddView(seen, &counts);
      std::vector<double> scores = PatchScores(counts, options.visibility);
      // Worst first; ties by patch order.
      std::vector<size_t> order(patches.size());
      std::iota(order.begin(), order.end(), 0);
      std::stable_sort(order.begin(), order.end(),
                       [&](size_t a, size_t b) { return scores[a] < scores[b]; });
      bool captured = false;
      for (const size_t p : order) {
        if (static_cast<int>(result.views.size()) >= options.max_views) break;
        if (scores[p] >= 1) break;
        const auto start = std::chrono::steady_clock::now();
        // Rank a candidate by the failing patches it would see (the paper takes the first).
        const auto rank = [&](const CellView& view) {
          int seen = 0;
          for (size_t q = 0; q < patches.size(); ++q) {
            // Cheap tests first: a passing patch, or one whose centre is not in the image.
            if (scores[q] >= 1 || !InImage(view.camera, patches[q].centre)) continue;
            seen += SeenFraction(*result.proxy, patches[q], view.camera, options.visibility) >=
                    options.visibility.min_seen_fraction;
          }
          return static_cast<double>(seen);
        };
        const SphereSearchResult found =
            SearchViewSphere(cell, *result.proxy, patches[p], search, joints, reach,
                             options.visibility, options.rank_candidates ? rank : ViewRank());
        result.iteration_seconds.push_back(
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        if (!found.view) continue;
        planning +=
            std::chrono::duration<double>(std::chrono::steady_clock::now() - round_start).count();
        const double before = scores[p];
        const Eigen::Vector3d& c = patches[p].centre;
        PlannedView planned{
            *found.view, "active",
            fmt::format("patch {} at ({:.3f}, {:.3f}, {:.3f}) m scored {:.2f}; "
                        "view sphere ring {} after {} candidates",
                        p, c.x(), c.y(), c.z(), before, found.ring, found.candidates),
            static_cast<int>(p), before};
        if (!Take(std::move(planned))) continue;
        captured = true;
        ++chosen;
        round_start = std::chrono::steady_clock::now();
        // Re-score this round's patches with the new view before the next failing one.
        AddView(PatchesSeenBy(*result.proxy, patches, result.views.back().view.camera,
                              options.visibility),
                &counts);
        scores = PatchScores(counts, options.visibility);
      }
      if (!captured) break;
    }
    result.planning_seconds_per_view = chosen > 0 ? planning / chosen : 0;
  }

  void RemoveRedundantAndRefine() {
    const std::vector<SurfacePatch> patches = ProxySurfacePatches(*result.proxy, options.patches);
    // Ordering by faces casts the rays per face once; the patches' verdicts follow from them.
    std::vector<PatchesSeen> faces, seen;
    if (options.remove_redundant && options.prune_order_by_faces) {
      faces = EveryView(patches, FacesSeenBy);
      for (const PatchesSeen& view : faces) {
        seen.push_back(PatchesSeenFromFaces(patches, view, options.visibility));
      }
    } else {
      seen = SeenByEveryView(patches);
    }
    std::vector<bool> keep(seen.size(), true);
    if (options.remove_redundant) {
      const PruneRule rule{options.prune_holds_failing_scores,
                           options.prune_max_covered_faces_lost};
      keep = KeepNonRedundant(seen, options.visibility, {}, rule, faces);
    }
    PatchViewCounts counts;
    for (size_t v = 0; v < seen.size(); ++v) {
      result.views[v].kept = keep[v];
      if (keep[v]) AddView(seen[v], &counts);
    }
    result.patches = static_cast<int>(patches.size());
    result.patch_scores = PatchScores(counts, options.visibility);
    result.failing_patches = static_cast<int>(std::count_if(
        result.patch_scores.begin(), result.patch_scores.end(), [](double s) { return s < 1; }));
    // The proxy from the kept views only, then at the final resolution (line 25).
    ppr::PlantProxy refined(result.proxy->box(), options.proxy);
    for (size_t v = 0; v < seen.size(); ++v) {
      if (keep[v]) refined.AddView(result.views[v].view.camera, masks[v]);
    }
    refined.IncreaseResolution();
    result.proxy = std::move(refined);
  }
};

}  // namespace

size_t ActiveVisionResult::KeptCount() const {
  return static_cast<size_t>(
      std::count_if(views.begin(), views.end(), [](const PlannedView& v) { return v.kept; }));
}

ActiveVisionResult RunActiveVision(const cell::CellModel& cell, const CaptureFunction& capture,
                                   const ActiveVisionOptions& options,
                                   const StageFunction& on_stage, const ProxyFunction& on_proxy) {
  if (options.levels < 1 || options.levels > static_cast<int>(options.elevations_deg.size())) {
    throw std::invalid_argument(fmt::format("active vision: {} heights but {} elevations given",
                                            options.levels, options.elevations_deg.size()));
  }
  const auto stage = [&](ActiveVisionStage next) {
    if (on_stage) on_stage(next);
  };
  Run run{cell, capture, options,  {},           {}, cell::StartJoints(cell),
          {},   stage,   on_proxy, options.reach};
  stage(ActiveVisionStage::kFrame);
  for (int level = 0; level < options.levels; ++level) run.InitialLevel(level);
  stage(ActiveVisionStage::kActiveVision);
  run.ActiveVision();
  stage(ActiveVisionStage::kPruneViews);
  run.RemoveRedundantAndRefine();
  run.result.framed_distances = run.distances;
  return std::move(run.result);
}

}  // namespace avc::planner
