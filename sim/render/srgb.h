#pragma once

// Linear 0..1 colour to 8-bit codes.

#include <array>
#include <cstdint>

namespace avc::sim {

// The sRGB transfer curve (IEC 61966-2-1) as a table fine enough (2^14 steps) that rounding, not
// the table, decides the code.
class SrgbTable {
 public:
  static const SrgbTable& Get();
  uint8_t Encode(float linear) const { return table_[Index(linear)]; }

 private:
  static constexpr int kSize = 1 << 14;
  SrgbTable();
  static int Index(float linear) {
    const float clamped = linear > 0.0f ? (linear < 1.0f ? linear : 1.0f) : 0.0f;  // NaN -> 0
    return static_cast<int>(clamped * (kSize - 1) + 0.5f);
  }
  std::array<uint8_t, kSize> table_;
};

// Plain scaling to 0..255, rounded.
inline uint8_t EncodeLinear(float linear) {
  const float clamped = linear > 0.0f ? (linear < 1.0f ? linear : 1.0f) : 0.0f;
  return static_cast<uint8_t>(clamped * 255.0f + 0.5f);
}

}  // namespace avc::sim
