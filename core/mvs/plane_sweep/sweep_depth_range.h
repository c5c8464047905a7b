#pragma once

// Per-pixel depth intervals to sweep in a reference view: from the plant proxy when there is
// one, else from a sphere every camera sees; restricted to the view's mask.

#include <Eigen/Core>
#include <vector>

#include "core/mvs/depth_range.h"
#include "core/mvs/mvs_bounds.h"
#include "core/mvs/plane_sweep/sweep_views.h"

namespace avc::mvs {

struct SceneSphere {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius = 0;
};

// The largest sphere around the point the cameras look at (NearestPointToAxes) that lies inside
// every camera's field of view: where a scene without a proxy can be.
SceneSphere CommonViewSphere(const std::vector<camera::Camera>& cameras);

// Proxy bounds (widened by margin_voxels voxel sizes) when not empty, else the sphere's
// ray intersection; zero outside the mask.
DepthRange SweepDepthRange(const SweepView& view, const MvsBounds& bounds,
                           const SceneSphere& sphere, double margin_voxels);

}  // namespace avc::mvs
