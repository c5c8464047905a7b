#pragma once

// Random vectors drawn in one fixed order. `Vector3(draw(), draw(), draw())` is not portable:
// C++ leaves the order in which a call's arguments are evaluated unspecified, and GCC evaluates
// the last argument first where clang evaluates the first, so the same seed made different data
// with each compiler. These draw the last coordinate first, the order GCC used, so the data sets
// measured so far (Table 2, the calibration and merge scenarios) keep their values.

namespace avc::util {

// (x, y, z) from three calls of `draw`, made in the order z, y, x.
template <typename Vector, typename Draw>
Vector DrawVector3(Draw&& draw) {
  const auto z = draw();
  const auto y = draw();
  const auto x = draw();
  return Vector(x, y, z);
}

}  // namespace avc::util
