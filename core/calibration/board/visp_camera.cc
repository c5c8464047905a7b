#include "core/calibration/board/visp_camera.h"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace avc::calibration {
namespace {

// The number inside the first <tag>...</tag>; 0 when an optional field is absent.
double ReadField(const std::string& text, const std::string& tag, const std::string& file,
                 bool required) {
  const std::string open = "<" + tag + ">", close = "</" + tag + ">";
  const size_t begin = text.find(open);
  if (begin == std::string::npos) {
    if (required)
      throw std::runtime_error(fmt::format("ViSP camera file '{}': no <{}> field", file, tag));
    return 0;
  }
  const size_t start = begin + open.size();
  const size_t end = text.find(close, start);
  if (end == std::string::npos)
    throw std::runtime_error(fmt::format("ViSP camera file '{}': <{}> is not closed", file, tag));
  const std::string value = text.substr(start, end - start);
  size_t used = 0;
  double number = 0;
  try {
    number = std::stod(value, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || !std::isfinite(number) ||
      value.find_first_not_of(" \t\r\n", used) != std::string::npos)
    throw std::runtime_error(
        fmt::format("ViSP camera file '{}': <{}> is not a number: '{}'", file, tag, value));
  return number;
}

}  // namespace

camera::Intrinsics ReadVispCameraXml(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in)
    throw std::runtime_error(fmt::format("cannot read ViSP camera file '{}'", path.string()));
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  const std::string file = path.string();
  camera::Intrinsics intrinsics;
  intrinsics.width = static_cast<int>(ReadField(text, "image_width", file, true));
  intrinsics.height = static_cast<int>(ReadField(text, "image_height", file, true));
  intrinsics.fx = ReadField(text, "px", file, true);
  intrinsics.fy = ReadField(text, "py", file, true);
  intrinsics.cx = ReadField(text, "u0", file, true);
  intrinsics.cy = ReadField(text, "v0", file, true);
  // ViSP's radial model is not OpenCV's; only the distortion-free case maps exactly.
  if (ReadField(text, "kud", file, false) != 0 || ReadField(text, "kdu", file, false) != 0)
    throw std::runtime_error(
        fmt::format("ViSP camera file '{}': radial distortion (kud/kdu) is not supported", file));
  if (const std::string problem = intrinsics.Validate(); !problem.empty())
    throw std::runtime_error(fmt::format("ViSP camera file '{}': {}", file, problem));
  return intrinsics;
}

}  // namespace avc::calibration
