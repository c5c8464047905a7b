#pragma once

// The emulated controller's RTDE variable table: which output and input names exist, their wire
// types (the strings the setup replies carry), and how they read from / write to the controller
// state. Names and types as in the UR RTDE guide.

#include <array>
#include <optional>
#include <string>

#include "drivers/robot/protocol/rtde_protocol.h"

namespace avc::sim::ur5 {

inline constexpr int kRegisterCount = 48;

struct ControllerState {
  double timestamp = 0;
  std::array<double, 6> actual_q{}, actual_qd{}, target_q{}, target_qd{};
  std::array<double, 6> actual_tcp_pose{}, target_tcp_pose{}, tcp_offset{};
  int32_t robot_mode = 3;
  int32_t safety_mode = 1;
  uint32_t safety_status_bits = 1;
  uint32_t runtime_state = 1;
  uint32_t robot_status_bits = 0;
  double speed_scaling = 1.0;
  double target_speed_fraction = 1.0;
  uint32_t speed_slider_mask = 0;
  double speed_slider_fraction = 1.0;
  uint64_t input_bit_registers = 0;  // bits 64..127
  std::array<int32_t, kRegisterCount> input_int{}, output_int{};
  std::array<double, kRegisterCount> input_double{}, output_double{};
};

// nullopt for names the controller does not know.
std::optional<robot::rtde::ValueType> OutputType(const std::string& name);
std::optional<robot::rtde::ValueType> InputType(const std::string& name);

// The value of a known output name (OutputType(name) has a value).
robot::rtde::Value OutputValue(const std::string& name, const ControllerState& state);
// Stores an input; the value's type matches InputType(name).
void WriteInput(const std::string& name, const robot::rtde::Value& value, ControllerState& state);

}  // namespace avc::sim::ur5
