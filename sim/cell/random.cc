#include "sim/cell/random.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace avc::sim {

double DeterministicRandom::Normal() {
  if (has_spare_normal_) {
    has_spare_normal_ = false;
    return spare_normal_;
  }
  const double u1 = 1.0 - Uniform01();  // (0, 1]: the logarithm stays finite
  const double u2 = Uniform01();
  const double radius = std::sqrt(-2.0 * std::log(u1));
  const double angle = 2.0 * std::numbers::pi * u2;
  spare_normal_ = radius * std::sin(angle);
  has_spare_normal_ = true;
  return radius * std::cos(angle);
}

Eigen::Vector3d DeterministicRandom::UnitVector() {
  // Archimedes: z uniform in [-1, 1] and a uniform azimuth cover the sphere uniformly.
  const double z = Symmetric(1.0);
  const double azimuth = 2.0 * std::numbers::pi * Uniform01();
  const double ring = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {ring * std::cos(azimuth), ring * std::sin(azimuth), z};
}

}  // namespace avc::sim
