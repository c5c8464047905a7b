#include "drivers/robot/robot_state.h"

#include <fmt/format.h>

#include <stdexcept>

namespace avc::robot {
namespace {

template <typename T>
const T& As(const rtde::Value& value, const std::string& name) {
  if (const T* typed = std::get_if<T>(&value)) return *typed;
  throw std::runtime_error(fmt::format("RTDE output '{}' arrived as {}, not the expected type",
                                       name, rtde::ValueTypeName(rtde::TypeOf(value))));
}

}  // namespace

const std::vector<std::string>& RobotStateOutputs() {
  static const std::vector<std::string> kOutputs = {
      "timestamp",       "actual_q",          "actual_qd",    "target_q",
      "actual_TCP_pose", "robot_mode",        "safety_mode",  "safety_status_bits",
      "runtime_state",   "robot_status_bits", "speed_scaling"};
  return kOutputs;
}

RobotState RobotStateFromPackage(const std::vector<std::string>& names,
                                 const std::vector<rtde::Value>& values) {
  if (names.size() != values.size()) {
    throw std::runtime_error(
        fmt::format("RTDE data package has {} values for {} outputs", values.size(), names.size()));
  }
  using Vector6 = std::array<double, 6>;
  RobotState state;
  for (size_t i = 0; i < names.size(); ++i) {
    const std::string& name = names[i];
    const rtde::Value& value = values[i];
    if (name == "timestamp") {
      state.timestamp = As<double>(value, name);
    } else if (name == "actual_q") {
      state.actual_q = As<Vector6>(value, name);
    } else if (name == "actual_qd") {
      state.actual_qd = As<Vector6>(value, name);
    } else if (name == "target_q") {
      state.target_q = As<Vector6>(value, name);
    } else if (name == "actual_TCP_pose") {
      state.actual_tcp_pose = As<Vector6>(value, name);
    } else if (name == "robot_mode") {
      state.robot_mode = static_cast<RobotMode>(As<int32_t>(value, name));
    } else if (name == "safety_mode") {
      state.safety_mode = static_cast<SafetyMode>(As<int32_t>(value, name));
    } else if (name == "safety_status_bits") {
      state.safety_status_bits = As<uint32_t>(value, name);
    } else if (name == "runtime_state") {
      state.runtime_state = static_cast<RuntimeState>(As<uint32_t>(value, name));
    } else if (name == "robot_status_bits") {
      state.robot_status_bits = As<uint32_t>(value, name);
    } else if (name == "speed_scaling") {
      state.speed_scaling = As<double>(value, name);
    }
  }
  return state;
}

}  // namespace avc::robot
