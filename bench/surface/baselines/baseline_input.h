#pragma once

// What every surface baseline checks and measures before meshing: a usable cloud (at least 3
// finite points, normals finite and one per point when given) and its point spacing, from which
// all of a baseline's distances are derived (the same measure the surfacer uses).

#include <string_view>

#include "core/geometry/point_cloud.h"

namespace avc::surface::baselines {

// Throws std::invalid_argument "<method>: <problem>" (too few points, a non-finite point or
// normal with its index, attributes of the wrong length). require_normals: the method needs
// oriented normals.
void CheckBaselineInput(const geometry::PointCloud& cloud, std::string_view method,
                        bool require_normals);

// spacing > 0: that; else the median nearest-neighbour distance of the points
// (cluster::EstimateDataScale). Throws std::invalid_argument naming the method when it cannot be
// measured (all points coincide).
double ResolveSpacing(const geometry::PointCloud& cloud, double spacing, std::string_view method);

}  // namespace avc::surface::baselines
