#pragma once

// The paper's Table 1 on a view set of `avc bench nbv`: the plant rendered in colour from each
// camera (at a fraction of its resolution, anti-aliased, as the cell's camera would see it), the
// builder run on the images as on a scan (lens undistortion, automatic masks, proxy, patch MVS),
// and its points scored against the plant's organs: how many per image and how far from them.

#include <nlohmann/json.hpp>
#include <vector>

#include "core/camera/pinhole_camera.h"
#include "core/geometry/mesh.h"
#include "sim/scene/scene.h"

namespace avc::bench {

// {"points", "points_per_image", "mean_distance_mm", "build_s"}; "build_error" instead when the
// builder refuses the set (e.g. too few views see the plant).
nlohmann::json BuildViewSet(const sim::Scene& scene, const std::vector<camera::Camera>& cameras,
                            double scale, const geometry::Mesh& organs);

}  // namespace avc::bench
