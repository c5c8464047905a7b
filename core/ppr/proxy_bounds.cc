#include "core/ppr/proxy_bounds.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/camera/axes_meeting_point.h"
#include "core/ppr/plant_proxy.h"

namespace avc::ppr {

Eigen::AlignedBox3d BoxFromCameras(const std::vector<camera::Camera>& cameras) {
  Eigen::Vector3d centre;
  try {
    centre = camera::AxesMeetingPoint(cameras);
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument(fmt::format("BoxFromCameras: {}", error.what()));
  }
  double half = 0;
  for (size_t i = 0; i < cameras.size(); ++i) {
    const auto& k = cameras[i].intrinsics;
    const double depth = (cameras[i].T_cam_world * centre).z();
    if (!(depth > 0)) {
      throw std::invalid_argument(fmt::format(
          "BoxFromCameras: the axes' meeting point is behind camera #{}: cameras do not look "
          "at a common object",
          i));
    }
    // Half the diagonal of the image at the object's distance.
    half = std::max(half, depth * std::hypot(k.width / (2 * k.fx), k.height / (2 * k.fy)));
  }
  return {centre.array() - half, centre.array() + half};
}

Eigen::AlignedBox3d BoundsFromViews(const std::vector<camera::Camera>& cameras,
                                    const std::vector<cv::Mat>& masks,
                                    const BoundsOptions& options) {
  if (cameras.empty()) throw std::invalid_argument("BoundsFromViews: no views");
  if (masks.size() != cameras.size()) {
    throw std::invalid_argument(
        fmt::format("BoundsFromViews: {} cameras but {} masks", cameras.size(), masks.size()));
  }
  if (options.coarse_cells < 4 || options.margin_cells < 0 || options.max_growth_steps < 0) {
    throw std::invalid_argument(
        "BoundsFromViews: coarse_cells must be >= 4, margin_cells and max_growth_steps >= 0");
  }
  Eigen::AlignedBox3d box = BoxFromCameras(cameras);
  ProxyOptions proxy_options;
  proxy_options.background_votes_allowed = options.background_votes_allowed;
  proxy_options.min_plant_views = options.min_plant_views;
  proxy_options.resolution_increases = 0;
  for (int step = 0;; ++step) {
    proxy_options.final_voxel_size = box.sizes().maxCoeff() / options.coarse_cells;
    PlantProxy proxy(box, proxy_options);
    for (size_t i = 0; i < cameras.size(); ++i) {
      proxy.AddView(cameras[i], masks[i], fmt::format("#{}", i));
    }
    const Eigen::AlignedBox3d survivors = proxy.OccupiedBounds();
    if (survivors.isEmpty()) {
      throw std::runtime_error(
          "BoundsFromViews: no voxel survived carving (empty masks, or the object is not where "
          "the cameras look)");
    }
    // Grow by half the box on every side the survivors touch, and carve again.
    const double touch = 1.5 * proxy.voxel_size();
    const Eigen::Array3d low_touch =
        ((survivors.min() - proxy.box().min()).array() < touch).cast<double>();
    const Eigen::Array3d high_touch =
        ((proxy.box().max() - survivors.max()).array() < touch).cast<double>();
    if (step < options.max_growth_steps && (low_touch.any() || high_touch.any())) {
      const Eigen::Array3d half = box.sizes().array() / 2;
      box = Eigen::AlignedBox3d(box.min().array() - low_touch * half,
                                box.max().array() + high_touch * half);
      continue;
    }
    const double margin = options.margin_cells * proxy.voxel_size();
    return {survivors.min().array() - margin, survivors.max().array() + margin};
  }
}

Eigen::AlignedBox3d BoundsFromViews(const std::vector<dataset::View>& views,
                                    const BoundsOptions& options) {
  std::vector<camera::Camera> cameras;
  std::vector<cv::Mat> masks;
  for (const auto& view : views) {
    if (view.mask.empty()) {
      throw std::invalid_argument(fmt::format("BoundsFromViews: view '{}' has no mask", view.name));
    }
    cameras.push_back(view.camera);
    masks.push_back(view.mask);
  }
  return BoundsFromViews(cameras, masks, options);
}

}  // namespace avc::ppr
