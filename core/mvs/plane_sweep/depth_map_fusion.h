#pragma once

// From per-view depth maps to MVS points: a pixel's depth is kept when its ZNCC passes the
// threshold and at least min_consistent_views other views' depth maps agree with it; its point
// is the mean of its own and the agreeing views' back-projected points, the normal comes from
// the reference depth map, the colour is the mean over the agreeing views. Points are then
// deduplicated on a cubic cell grid (the most confident point per cell) and, with a proxy,
// restricted to it (one voxel of dilation).

#include <vector>

#include "core/mvs/mvs_bounds.h"
#include "core/mvs/mvs_points.h"
#include "core/mvs/plane_sweep/plane_sweep_mvs.h"
#include "core/mvs/plane_sweep/sweep_depth_map.h"
#include "core/mvs/plane_sweep/sweep_views.h"

namespace avc::mvs {

MvsPoints FuseDepthMaps(const std::vector<SweepView>& views,
                        const std::vector<SweepDepthMap>& depth_maps, const MvsBounds& bounds,
                        const PlaneSweepOptions& options);

}  // namespace avc::mvs
