#pragma once

// The information-gain planner the active vision is compared with (Isler et al., ICRA 2016, the
// "unobserved voxel" gain). Candidate views lie on a sphere around the
// plant (elevation rings x azimuths, realised in the cell as the planner's own are). Each step
// scores every reachable candidate by casting rays through a grid of its pixels into the plant
// proxy and counting the unknown voxels they cross before an occupied one; the best is captured
// and carved into the proxy. Greedy, no redundancy removal, `count` views in all.

#include <Eigen/Geometry>
#include <vector>

#include "core/ppr/plant_proxy.h"
#include "services/planner/active_vision.h"
#include "services/planner/cell_view.h"
#include "sim/cell/cell_truth.h"

namespace avc::planner {

struct InformationGainOptions {
  std::vector<double> elevations_deg = {10, 25, 40, 55, 70};
  int azimuths = 24;
  int ray_step_px = 40;  // one ray per this many pixels each way
  ppr::ProxyOptions proxy;
};

// The unknown voxels of `proxy` that rays through every ray_step_px-th pixel of `camera` cross
// before they reach an occupied voxel (or leave the proxy's box).
size_t UnobservedVoxelGain(const ppr::PlantProxy& proxy, const camera::Camera& camera,
                           int ray_step_px);

// Views in capture order (fewer than `count` when captures fail or no candidate is left).
std::vector<CellView> InformationGainViews(const sim::CellTruth& cell,
                                           const CaptureFunction& capture,
                                           const Eigen::AlignedBox3d& box,
                                           const Eigen::Vector3d& aim, double distance, int count,
                                           const InformationGainOptions& options = {});

}  // namespace avc::planner
