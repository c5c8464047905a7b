#pragma once

// PCL region growing baseline (Rabbani et al. 2006, pcl::RegionGrowing): grows regions from the
// lowest-curvature seeds across neighbours whose normals differ by less than the smoothness
// threshold; only low-curvature members keep growing. Normals come from the PointSet; curvature
// is estimated by PCA over the same neighbourhood.

#include <cstdint>

#include "core/cluster/point_set.h"

namespace avc::cluster::baselines {

struct RegionGrowingOptions {
  double smoothness_degrees = 10.0;  // 8-15 degrees split non-touching synthetic leaves cleanly
  // Members above this curvature join a region but do not extend it; <= 0: the
  // curvature_quantile of the set's curvatures (derived from data).
  double curvature_threshold = 0.0;
  double curvature_quantile = 0.9;
  int neighbours = 20;
  int min_cluster_size = 10;  // smaller regions are left kUnassigned
};

// Throws std::invalid_argument for an empty or non-finite set, missing normals or bad options.
Assignment RegionGrowingClustering(const PointSet& set, const RegionGrowingOptions& options);

}  // namespace avc::cluster::baselines
