#include "sim/render/srgb.h"

#include <algorithm>
#include <cmath>

namespace avc::sim {

SrgbTable::SrgbTable() {
  for (int i = 0; i < kSize; ++i) {
    const double linear = static_cast<double>(i) / (kSize - 1);
    const double encoded =
        linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
    table_[i] = static_cast<uint8_t>(std::clamp(std::lround(encoded * 255.0), 0L, 255L));
  }
}

const SrgbTable& SrgbTable::Get() {
  static const SrgbTable table;
  return table;
}

}  // namespace avc::sim
