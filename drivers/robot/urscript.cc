#include "drivers/robot/urscript.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace avc::robot {
namespace {

constexpr std::string_view kProgramName = "avc_motion";

// Nine decimals: 1e-9 rad and 1 nm, well below the controller's resolution.
std::string List(const std::array<double, 6>& values, std::string_view what) {
  std::string text = "[";
  for (size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) {
      throw std::invalid_argument(fmt::format("URScript {}: entry {} is not finite", what, i));
    }
    text += fmt::format("{}{:.9f}", i ? ", " : "", values[i]);
  }
  return text + "]";
}

void CheckRate(double value, std::string_view what) {
  if (!(std::isfinite(value) && value > 0)) {
    throw std::invalid_argument(fmt::format("URScript {} must be positive, got {}", what, value));
  }
}

std::string Program(const std::string& body) {
  return fmt::format("def {}():\n  {}\nend\n", kProgramName, body);
}

}  // namespace

std::string MoveJProgram(const Joints& q, double acceleration, double velocity) {
  CheckRate(acceleration, "movej acceleration");
  CheckRate(velocity, "movej velocity");
  return Program(fmt::format("movej({}, a={:.6f}, v={:.6f})", List(q, "movej joints"), acceleration,
                             velocity));
}

std::string MoveLProgram(const PoseVector& pose, double acceleration, double velocity) {
  CheckRate(acceleration, "movel acceleration");
  CheckRate(velocity, "movel velocity");
  return Program(fmt::format("movel(p{}, a={:.6f}, v={:.6f})", List(pose, "movel pose"),
                             acceleration, velocity));
}

std::string StopJProgram(double deceleration) {
  CheckRate(deceleration, "stopj deceleration");
  return Program(fmt::format("stopj({:.6f})", deceleration));
}

}  // namespace avc::robot
