#pragma once

// Cheap, seeded, allocation-free 2D noise for procedural textures: a pure function of its
// arguments, bit-identical across runs (integer hashing, no library distributions).

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace avc::sim::noise {

// Well-mixed 32-bit hash of a lattice cell and a seed (murmur3 finaliser).
inline uint32_t HashCell(int32_t x, int32_t y, uint32_t seed) {
  uint32_t h = static_cast<uint32_t>(x) * 0x8da6b343u ^ static_cast<uint32_t>(y) * 0xd8163841u ^
               seed * 0xcb1ab31fu;
  h ^= h >> 16;
  h *= 0x85ebca6bu;
  h ^= h >> 13;
  h *= 0xc2b2ae35u;
  h ^= h >> 16;
  return h;
}

// Uniform in [0, 1) from the top 24 bits of a hash.
inline float UnitFromHash(uint32_t h) { return static_cast<float>(h >> 8) * (1.0f / 16777216.0f); }

// floor() as an integer without a library call (x86-64 baseline has no rounding instruction).
// Inputs beyond the int32 range (or NaN) give a meaningless but defined cell.
inline int32_t FloorToInt(float x) {
  if (!(std::abs(x) < 2.0e9f)) return 0;
  const int32_t i = static_cast<int32_t>(x);
  return x < static_cast<float>(i) ? i - 1 : i;
}

// Per-cell constant value in [0, 1): blocky grain.
inline float CellValue(float x, float y, uint32_t seed) {
  return UnitFromHash(HashCell(FloorToInt(x), FloorToInt(y), seed));
}

// Smoothly interpolated value noise in [0, 1) with unit lattice spacing.
inline float ValueNoise(float x, float y, uint32_t seed) {
  const int32_t ix = FloorToInt(x);
  const int32_t iy = FloorToInt(y);
  const float tx = std::clamp(x - static_cast<float>(ix), 0.0f, 1.0f);
  const float ty = std::clamp(y - static_cast<float>(iy), 0.0f, 1.0f);
  const float sx = tx * tx * (3.0f - 2.0f * tx);
  const float sy = ty * ty * (3.0f - 2.0f * ty);
  const float v00 = UnitFromHash(HashCell(ix, iy, seed));
  const float v10 = UnitFromHash(HashCell(ix + 1, iy, seed));
  const float v01 = UnitFromHash(HashCell(ix, iy + 1, seed));
  const float v11 = UnitFromHash(HashCell(ix + 1, iy + 1, seed));
  const float a = v00 + (v10 - v00) * sx;
  const float b = v01 + (v11 - v01) * sx;
  return a + (b - a) * sy;
}

// Intensity of a line seen at `distance` from its centre: 1 on the centre, falling smoothly to 0
// at half_width.
inline float LineProfile(float distance, float half_width) {
  const float t = std::clamp(distance / half_width, 0.0f, 1.0f);
  return 1.0f - t * t * (3.0f - 2.0f * t);
}

}  // namespace avc::sim::noise
