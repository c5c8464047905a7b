#pragma once

// Random numbers that are the same bits with every standard library: std::mt19937_64's output
// is fixed by the standard, while std::uniform_real_distribution and friends are not, so the
// mappings from engine bits to numbers are our own.

#include <Eigen/Core>
#include <cstdint>
#include <random>

namespace avc::sim {

class DeterministicRandom {
 public:
  explicit DeterministicRandom(uint64_t seed) : engine_(seed) {}

  uint64_t Bits() { return engine_(); }
  // Uniform in [0, 1) with 53 random bits.
  double Uniform01() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double Uniform(double lo, double hi) { return lo + (hi - lo) * Uniform01(); }
  // Uniform in [-half_width, half_width).
  double Symmetric(double half_width) { return half_width * (2 * Uniform01() - 1); }
  // Standard normal by the Box-Muller transform; both values of a pair are used in turn.
  double Normal();
  // Uniform on the unit sphere.
  Eigen::Vector3d UnitVector();

 private:
  std::mt19937_64 engine_;
  double spare_normal_ = 0;
  bool has_spare_normal_ = false;
};

}  // namespace avc::sim
