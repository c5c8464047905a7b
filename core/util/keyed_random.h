#pragma once

// Deterministic pseudo-random values keyed by what they describe (a seed and a key such as a
// joint angle's bits or a trial number) instead of by how many draws came before. A value that
// depends on draw order changes when timing changes the number of draws (a control loop that
// ticks once more, a command sent twice after a restart); a keyed value does not.

#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace avc::util {

// The SplitMix64 finaliser of seed + golden-ratio * (key + 1): well-separated 64-bit values for
// neighbouring keys.
constexpr uint64_t MixSeed(uint64_t seed, uint64_t key) {
  uint64_t z = seed + 0x9e3779b97f4a7c15ULL * (key + 1);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// A double in [0, 1) from the top 53 bits (our own mapping: the same on every standard library).
constexpr double UnitFromBits(uint64_t bits) { return static_cast<double>(bits >> 11) * 0x1.0p-53; }

// The key of a double: its bit pattern (equal values give equal keys; +0 and -0 differ).
inline uint64_t KeyOf(double value) { return std::bit_cast<uint64_t>(value); }

// Uniform in [-1, 1) for (seed, key).
constexpr double SignedUnitFor(uint64_t seed, uint64_t key) {
  return 2 * UnitFromBits(MixSeed(seed, key)) - 1;
}

// A standard normal value for (seed, key) (Box-Muller on two derived values).
inline double GaussianFor(uint64_t seed, uint64_t key) {
  const uint64_t first = MixSeed(seed, key);
  const double u1 = UnitFromBits(first) + 0x1.0p-53;  // (0, 1]: log stays finite
  const double u2 = UnitFromBits(MixSeed(first, key));
  return std::sqrt(-2 * std::log(u1)) * std::cos(2 * std::numbers::pi * u2);
}

}  // namespace avc::util
