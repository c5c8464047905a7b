#pragma once

// Seeded random numbers for the plant generator, mapped from raw std::mt19937 bits by our own
// arithmetic so plants are bit-identical across standard library versions.

#include <cstdint>
#include <random>

namespace avc::sim {

class PlantRandom {
 public:
  explicit PlantRandom(uint32_t seed) : engine_(seed) {}

  // Uniform in [lo, hi).
  float Uniform(float lo, float hi) {
    const float unit = static_cast<float>(engine_() >> 8) * (1.0f / 16777216.0f);
    return lo + (hi - lo) * unit;
  }
  // Uniform integer in [lo, hi].
  int Int(int lo, int hi) {
    const uint64_t span = static_cast<uint64_t>(hi - lo) + 1;
    return lo + static_cast<int>((static_cast<uint64_t>(engine_()) * span) >> 32);
  }
  // Raw 32 bits (e.g. to seed a texture).
  uint32_t Bits() { return static_cast<uint32_t>(engine_()); }

 private:
  std::mt19937 engine_;
};

}  // namespace avc::sim
