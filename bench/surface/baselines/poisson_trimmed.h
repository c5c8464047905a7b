#pragma once

// Baseline: screened Poisson reconstruction (Kazhdan & Hoppe 2013, pcl::Poisson) trimmed to the
// data. Poisson always closes the surface, so an open leaf comes back as a blob wrapped round
// both sides (RMSE ~25 mm, area ~4x on our plants); faces whose centroid is farther
// than trim_factor spacings from every input point are dropped.

#include "core/geometry/mesh.h"
#include "core/geometry/point_cloud.h"

namespace avc::surface::baselines {

struct PoissonOptions {
  double spacing = 0;  // m; <= 0: measured (median nearest-neighbour distance)
  // Octree depth; <= 0: the depth whose finest cell is no larger than the spacing over the
  // cloud's bounding cube (PCL's default scale 1.1), clamped to [6, 10]: finer cells than the
  // samples only fit noise, coarser ones lose leaves.
  int depth = 0;
  // Drop faces farther than this many spacings from the data: the surface between two
  // neighbouring samples is at most about one spacing away, so 2 keeps the sampled sheet and
  // cuts the far side of the blob (BENCHMARKS.md, surface, measures it trimmed at 2 h).
  double trim_factor = 2.0;
};

// Needs oriented normals. Throws std::invalid_argument naming the problem for bad input (fewer
// than 3 points, non-finite points or normals, no normals).
geometry::Mesh PoissonTrimmed(const geometry::PointCloud& cloud,
                              const PoissonOptions& options = {});

}  // namespace avc::surface::baselines
