#pragma once

// Floor and ceiling of integer division by a positive divisor, through a double division (much
// cheaper than a 64-bit integer division in the rasteriser's per-triangle setup). Exact while
// |a| < 2^40 and 0 < b < 2^12: the rounding error of a / b stays far below the 1/b gap to the
// nearest integer, so the truncation never crosses one.

#include <cstdint>

namespace avc::sim {

inline int64_t FloorDiv(int64_t a, int64_t b) {
  const double q = static_cast<double>(a) / static_cast<double>(b);
  const int64_t t = static_cast<int64_t>(q);
  return t - (static_cast<double>(t) > q);
}

inline int64_t CeilDiv(int64_t a, int64_t b) { return -FloorDiv(-a, b); }

}  // namespace avc::sim
