#pragma once

// The circumradius of a triangle, the alpha-shape test of Phase 1 and of the grown regions.

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <utility>

namespace avc::surface {

// abc / (4 area) in 2-D or 3-D; infinite when degenerate.
template <int N>
double Circumradius(const Eigen::Matrix<double, N, 1>& a, const Eigen::Matrix<double, N, 1>& b,
                    const Eigen::Matrix<double, N, 1>& c) {
  const double ab = (b - a).norm();
  const double bc = (c - b).norm();
  const double ca = (a - c).norm();
  // Heron's formula in its stable form (sides sorted), valid in any dimension.
  double x = ab, y = bc, z = ca;
  if (x < y) std::swap(x, y);
  if (x < z) std::swap(x, z);
  if (y < z) std::swap(y, z);
  const double product = (x + (y + z)) * (z - (x - y)) * (z + (x - y)) * (x + (y - z));
  if (!(product > 0.0)) return std::numeric_limits<double>::infinity();
  return ab * bc * ca / std::sqrt(product);
}

}  // namespace avc::surface
