#pragma once

// Baseline: CGAL's advancing front surface reconstruction (Cohen-Steiner & Da 2004):
// interpolating, greedy over the 3-D Delaunay triangulation, no normals needed. Unbounded it
// bridges neighbouring leaves (errors of several mm on synthetic plants), so facets whose perimeter
// exceeds a bound are refused.

#include "core/geometry/mesh.h"
#include "core/geometry/point_cloud.h"

namespace avc::surface::baselines {

struct AdvancingFrontOptions {
  double spacing = 0;  // m; <= 0: measured (median nearest-neighbour distance)
  // Facets with a perimeter over this many spacings (median nearest-neighbour distances h) are
  // refused. An earlier trial on synthetic leaves found 6 mean spacings (~2.1 h on a random
  // sampling) the best bound: 12 h, an equilateral facet of edge 4 h, about twice a random
  // sampling's mean Delaunay edge (1.13 / sqrt(rho) = 2.4 h). Measured on a 2000-point cylinder
  // sheet: area 0.09 at 6 h, 0.51 at 10 h, 0.73-0.76 at 12 h, 0.93 at 16 h (bridging gaps).
  double max_perimeter_factor = 12.0;
  double radius_ratio_bound = 5.0;  // CGAL's defaults
  double beta = 0.52;
};

// Throws std::invalid_argument naming the problem for bad input (fewer than 3 points,
// non-finite points).
geometry::Mesh AdvancingFront(const geometry::PointCloud& cloud,
                              const AdvancingFrontOptions& options = {});

}  // namespace avc::surface::baselines
