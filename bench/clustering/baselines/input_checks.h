#pragma once

// Input validation shared by the baselines: each throws std::invalid_argument naming the method
// and the offending point.

#include <cstddef>
#include <string_view>

#include "core/cluster/point_set.h"

namespace avc::cluster::baselines {

// Non-empty, every coordinate finite.
void CheckPoints(const PointSet& set, std::string_view method);
// One finite, non-zero normal per point.
void CheckNormals(const PointSet& set, std::string_view method);
// 1 <= clusters <= number of points.
void CheckClusterCount(int clusters, size_t points, std::string_view method);

}  // namespace avc::cluster::baselines
