#pragma once

// The upper median: the element at position size / 2 once sorted (the middle one, or the upper
// of the two middle ones), found by partial sorting in linear time; T{} for no values.

#include <algorithm>
#include <cstddef>
#include <vector>

namespace avc {

template <typename T>
T UpperMedian(std::vector<T> values) {
  if (values.empty()) return T{};
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

}  // namespace avc
