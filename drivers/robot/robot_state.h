#pragma once

// The controller state the driver works from, as read from one RTDE data package.

#include <array>
#include <string>
#include <vector>

#include "drivers/robot/protocol/rtde_protocol.h"
#include "drivers/robot/protocol/ur_modes.h"

namespace avc::robot {

struct RobotState {
  double timestamp = 0;  // controller time, s
  std::array<double, 6> actual_q{};
  std::array<double, 6> actual_qd{};
  std::array<double, 6> target_q{};
  std::array<double, 6> actual_tcp_pose{};  // x y z (m), rotation vector (rad), in base
  RobotMode robot_mode = RobotMode::kDisconnected;
  SafetyMode safety_mode = SafetyMode::kNormal;
  uint32_t safety_status_bits = 0;
  RuntimeState runtime_state = RuntimeState::kStopped;
  uint32_t robot_status_bits = 0;
  double speed_scaling = 1.0;
};

// The outputs RobotState reads; a recipe with these fills every field.
const std::vector<std::string>& RobotStateOutputs();

// Copies the values of the known names into a RobotState (unknown names are ignored, missing
// ones keep their defaults). Throws std::runtime_error when a known name has the wrong type.
RobotState RobotStateFromPackage(const std::vector<std::string>& names,
                                 const std::vector<rtde::Value>& values);

}  // namespace avc::robot
