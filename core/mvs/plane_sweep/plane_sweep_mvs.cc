#include "core/mvs/plane_sweep/plane_sweep_mvs.h"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <mutex>
#include <stdexcept>

#include "core/mvs/plane_sweep/depth_map_fusion.h"
#include "core/mvs/plane_sweep/sweep_depth_map.h"
#include "core/mvs/plane_sweep/sweep_depth_range.h"
#include "core/mvs/plane_sweep/sweep_views.h"
#include "core/mvs/view_neighbours.h"
#include "core/util/validation.h"

namespace avc::mvs {
std::string PlaneSweepOptions::Validate() const {
  FirstProblem problem;
  const auto Require = [&problem](bool ok, const std::string& what) {
    problem.Require(ok, "PlaneSweepOptions: " + what);
  };
  Require(level >= -1 && level <= 8, fmt::format("level {} is not -1 (auto) or 0..8", level));
  Require(window >= 3 && window % 2 == 1, fmt::format("window {} is not odd and >= 3", window));
  Require(neighbours >= 1 && neighbours <= 16,
          fmt::format("neighbours {} not in 1..16", neighbours));
  Require(best_k >= 1 && best_k <= neighbours,
          fmt::format("best_k {} not in 1..neighbours ({})", best_k, neighbours));
  Require(max_plane_step_px > 0 && std::isfinite(max_plane_step_px),
          "max_plane_step_px must be positive");
  Require(max_planes >= 2, fmt::format("max_planes {} is below 2", max_planes));
  Require(depth_margin_voxels >= 0 && std::isfinite(depth_margin_voxels),
          "depth_margin_voxels must be >= 0");
  Require(min_texture_std >= 0 && std::isfinite(min_texture_std), "min_texture_std must be >= 0");
  Require(min_score >= -1 && min_score <= 1, fmt::format("min_score {} not in -1..1", min_score));
  Require(consistency_tolerance > 0 && std::isfinite(consistency_tolerance),
          "consistency_tolerance must be positive");
  Require(min_consistent_views >= 0, "min_consistent_views must be >= 0");
  Require(cell_px >= 0 && std::isfinite(cell_px), "cell_px must be >= 0");
  Require(normal_step_px >= 1, "normal_step_px must be >= 1");
  return problem.text();
}

MvsPoints RunPlaneSweep(const std::vector<dataset::View>& views, const MvsBounds& bounds,
                        const PlaneSweepOptions& options, const MvsProgress& progress) {
  RequireValid(options);
  ValidateSweepInputs(views);
  if (!bounds.empty() && !(bounds.voxel_size > 0)) {
    throw std::invalid_argument("MvsBounds: voxel_size must be positive when voxels are given");
  }
  for (size_t i = 0; i < bounds.occupied_centres.size(); ++i) {
    if (!bounds.occupied_centres[i].allFinite()) {
      throw std::invalid_argument(fmt::format("MvsBounds: occupied centre {} is not finite", i));
    }
  }
  const int level = ChooseSweepLevel(views, options.level);
  const std::vector<SweepView> prepared = PrepareSweepViews(views, level);

  std::vector<camera::Camera> cameras;
  for (const SweepView& view : prepared) cameras.push_back(view.camera);
  const SceneSphere sphere = CommonViewSphere(cameras);
  Eigen::Vector3d scene_centre = sphere.centre;
  if (!bounds.empty()) {
    scene_centre.setZero();
    for (const Eigen::Vector3f& c : bounds.occupied_centres) scene_centre += c.cast<double>();
    scene_centre /= static_cast<double>(bounds.occupied_centres.size());
  }
  NeighbourOptions neighbour_options;
  neighbour_options.max_neighbours = options.neighbours;
  const std::vector<std::vector<uint32_t>> neighbours =
      SelectNeighbours(cameras, scene_centre, neighbour_options);

  // Depth maps, one reference view per task: each writes only its own slot.
  std::vector<SweepDepthMap> depth_maps(prepared.size());
  std::mutex progress_mutex;
  size_t done = 0;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, prepared.size(), 1),
                    [&](const tbb::blocked_range<size_t>& range) {
                      for (size_t r = range.begin(); r != range.end(); ++r) {
                        std::vector<const SweepView*> others;
                        for (uint32_t n : neighbours[r]) others.push_back(&prepared[n]);
                        const DepthRange depth_range = SweepDepthRange(prepared[r], bounds, sphere,
                                                                       options.depth_margin_voxels);
                        depth_maps[r] = SweepReference(prepared[r], others, depth_range, options);
                        if (progress) {
                          const std::lock_guard<std::mutex> lock(progress_mutex);
                          progress("plane sweep", ++done, prepared.size());
                        }
                      }
                    });
  if (progress) progress("fusion", 0, 1);
  MvsPoints points = FuseDepthMaps(prepared, depth_maps, bounds, options);
  if (progress) progress("fusion", 1, 1);
  return points;
}

}  // namespace avc::mvs
