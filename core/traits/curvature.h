#pragma once

// Discrete mean curvature of a triangle mesh: |H| at each interior vertex from the cotangent
// Laplacian (Meyer et al. 2003, with barycentric vertex areas), summarised over the surface.
// Boundary vertices are left out: the cotangent formula does not hold there.

#include <cstddef>

#include "core/geometry/mesh.h"

namespace avc::traits {

struct CurvatureSummary {
  size_t vertices = 0;  // interior vertices measured
  double mean = 0;      // area-weighted mean of |H| (1/m)
  double median = 0;    // median of |H| over the vertices
  double p90 = 0;       // 90th percentile of |H|
};

CurvatureSummary SummarizeMeanCurvature(const geometry::Mesh& mesh);

}  // namespace avc::traits
