#include "report/report_encode.h"

#include <fmt/format.h>

#include <cmath>
#include <cstring>

#include "core/util/web_text.h"

namespace avc::report {
namespace {

// Appends the value's bytes least significant first, whatever the host's order.
void AppendLittleEndian(uint32_t value, std::vector<uint8_t>* bytes) {
  for (int shift = 0; shift < 32; shift += 8) bytes->push_back((value >> shift) & 0xff);
}

}  // namespace

std::string Base64Floats(const std::vector<float>& values) {
  std::vector<uint8_t> bytes;
  bytes.reserve(values.size() * 4);
  for (float v : values) {
    uint32_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    AppendLittleEndian(bits, &bytes);
  }
  return Base64Encode(bytes);
}

std::string Base64Ints(const std::vector<int32_t>& values) {
  std::vector<uint8_t> bytes;
  bytes.reserve(values.size() * 4);
  for (int32_t v : values) AppendLittleEndian(static_cast<uint32_t>(v), &bytes);
  return Base64Encode(bytes);
}

std::array<uint8_t, 3> ClusterColour(int32_t cluster) {
  if (cluster < 0) return {150, 150, 150};
  // Golden-angle hue steps keep neighbouring ids apart; saturation and value alternate a little
  // so ids 20 apart stay distinguishable.
  const double hue = std::fmod(cluster * 137.508, 360.0) / 60.0;
  const double s = cluster % 2 ? 0.55 : 0.75;
  const double v = cluster % 3 == 1 ? 0.80 : 0.95;
  const double c = v * s;
  const double x = c * (1 - std::fabs(std::fmod(hue, 2.0) - 1));
  double r = 0, g = 0, b = 0;
  switch (static_cast<int>(hue)) {
    case 0:
      r = c, g = x;
      break;
    case 1:
      r = x, g = c;
      break;
    case 2:
      g = c, b = x;
      break;
    case 3:
      g = x, b = c;
      break;
    case 4:
      r = x, b = c;
      break;
    default:
      r = c, b = x;
      break;
  }
  const double m = v - c;
  auto byte = [m](double channel) {
    return static_cast<uint8_t>(std::lround((channel + m) * 255));
  };
  return {byte(r), byte(g), byte(b)};
}

std::string CssColour(const std::array<uint8_t, 3>& rgb) {
  return fmt::format("#{:02x}{:02x}{:02x}", rgb[0], rgb[1], rgb[2]);
}

}  // namespace avc::report
