#pragma once

// Baseline: greedy projection triangulation (Marton et al. 2009,
// pcl::GreedyProjectionTriangulation): fast and interpolating, leaves holes where the sampling is
// sparse (BENCHMARKS.md, surface).

#include "core/geometry/mesh.h"
#include "core/geometry/point_cloud.h"

namespace avc::surface::baselines {

struct GreedyProjectionOptions {
  double spacing = 0;  // m; <= 0: measured (median nearest-neighbour distance)
  // Neighbourhood radius in spacings (median nearest-neighbour distances h). On a random
  // sampling of density rho, h = 0.47 / sqrt(rho) while the mean distance between neighbours
  // (an earlier trial on synthetic leaves found 3 of those the best radius) is about 1 /
  // sqrt(rho) = 2.1 h: 6 h. Measured on a 2000-point cylinder sheet: area 0.15 at 3 h, 0.56 at
  // 5 h, 0.68 at 6 h, 0.71-0.76 at 8 h (where it starts bridging gaps).
  double radius_factor = 6.0;
  // Edges up to mu times the local nearest-neighbour distance (PCL recommends 2.5-3; a random
  // sampling's nearest neighbour is often much closer than its typical neighbour: 3).
  double mu = 3.0;
  int max_neighbours = 100;
  double max_surface_angle_deg = 45.0;  // neighbours whose normals differ more are not linked
  double min_angle_deg = 10.0;
  double max_angle_deg = 120.0;
};

// Needs oriented normals. Throws std::invalid_argument naming the problem for bad input.
geometry::Mesh GreedyProjection(const geometry::PointCloud& cloud,
                                const GreedyProjectionOptions& options = {});

}  // namespace avc::surface::baselines
