#include "bench/nbv/information_gain.h"

#include <octomap/OcTree.h>
#include <tbb/parallel_for.h>

#include <cmath>

#include "bench/nbv/baseline_views.h"

namespace avc::planner {
namespace {

octomap::point3d Point(const Eigen::Vector3d& p) {
  return octomap::point3d(static_cast<float>(p.x()), static_cast<float>(p.y()),
                          static_cast<float>(p.z()));
}

// The part [t0, t1] of the ray origin + t * direction inside `box`; false when it misses.
bool ClipToBox(const Eigen::AlignedBox3d& box, const Eigen::Vector3d& origin,
               const Eigen::Vector3d& direction, double* t0, double* t1) {
  *t0 = 0;
  *t1 = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a) {
    if (std::abs(direction[a]) < 1e-12) {
      if (origin[a] < box.min()[a] || origin[a] > box.max()[a]) return false;
      continue;
    }
    double near = (box.min()[a] - origin[a]) / direction[a];
    double far = (box.max()[a] - origin[a]) / direction[a];
    if (near > far) std::swap(near, far);
    *t0 = std::max(*t0, near);
    *t1 = std::min(*t1, far);
  }
  return *t0 < *t1;
}

}  // namespace

size_t UnobservedVoxelGain(const ppr::PlantProxy& proxy, const camera::Camera& camera,
                           int ray_step_px) {
  const octomap::OcTree& tree = proxy.tree();
  const Eigen::AlignedBox3d box = proxy.box();
  const Eigen::Vector3d eye = camera.T_cam_world.inverse().translation();
  const Eigen::Matrix3d r_world_cam = camera.T_cam_world.linear().transpose();
  const camera::Intrinsics& k = camera.intrinsics;
  size_t gain = 0;
  octomap::KeyRay keys;
  for (int v = ray_step_px / 2; v < k.height; v += ray_step_px) {
    for (int u = ray_step_px / 2; u < k.width; u += ray_step_px) {
      const Eigen::Vector3d direction = r_world_cam * k.Ray(Eigen::Vector2d(u, v));
      double t0 = 0, t1 = 0;
      if (!ClipToBox(box, eye, direction, &t0, &t1)) continue;
      if (!tree.computeRayKeys(Point(eye + t0 * direction), Point(eye + t1 * direction), keys)) {
        continue;
      }
      for (const octomap::OcTreeKey& key : keys) {
        const octomap::OcTreeNode* node = tree.search(key);
        if (node == nullptr) {
          ++gain;
        } else if (tree.isNodeOccupied(node)) {
          break;
        }
      }
    }
  }
  return gain;
}

std::vector<CellView> InformationGainViews(const sim::CellTruth& cell,
                                           const CaptureFunction& capture,
                                           const Eigen::AlignedBox3d& box,
                                           const Eigen::Vector3d& aim, double distance, int count,
                                           const InformationGainOptions& options) {
  std::vector<double> elevations;
  for (const double degrees : options.elevations_deg) elevations.push_back(degrees * M_PI / 180);
  const std::vector<CellView> candidates =
      SphereViews(cell, {aim, distance}, elevations, options.azimuths);
  ppr::PlantProxy proxy(box, options.proxy);
  std::vector<CellView> chosen;
  std::vector<bool> used(candidates.size(), false);
  while (static_cast<int>(chosen.size()) < count) {
    std::vector<size_t> gains(candidates.size(), 0);
    proxy.tree();  // built here: the scoring below reads it from several threads
    tbb::parallel_for(size_t{0}, candidates.size(), [&](size_t c) {
      if (!used[c])
        gains[c] = UnobservedVoxelGain(proxy, candidates[c].camera, options.ray_step_px);
    });
    size_t best = candidates.size();
    for (size_t c = 0; c < candidates.size(); ++c) {
      if (!used[c] && (best == candidates.size() || gains[c] > gains[best])) best = c;
    }
    if (best == candidates.size()) break;
    used[best] = true;
    const std::optional<cv::Mat> mask = capture(candidates[best]);
    if (!mask) continue;
    proxy.AddView(candidates[best].camera, *mask);
    chosen.push_back(candidates[best]);
  }
  return chosen;
}

}  // namespace avc::planner
