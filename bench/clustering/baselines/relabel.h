#pragma once

// Canonical cluster ids, so equal partitions compare equal whatever order a method found them in.

#include "core/cluster/point_set.h"

namespace avc::cluster::baselines {

// Renumbers clusters 0, 1, ... in the order of their first point; kUnassigned stays.
Assignment RelabelByFirstAppearance(const Assignment& assignment);

}  // namespace avc::cluster::baselines
