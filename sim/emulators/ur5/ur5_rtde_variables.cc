#include "sim/emulators/ur5/ur5_rtde_variables.h"

#include <charconv>
#include <map>
#include <stdexcept>

namespace avc::sim::ur5 {
namespace {

using robot::rtde::Value;
using robot::rtde::ValueType;

// "input_int_register_7" with prefix "input_int_register_" -> 7 when within [low, high).
std::optional<int> RegisterIndex(const std::string& name, std::string_view prefix, int low,
                                 int high) {
  if (name.rfind(prefix, 0) != 0) return std::nullopt;
  const char* begin = name.data() + prefix.size();
  const char* end = name.data() + name.size();
  int index = 0;
  const auto [ptr, ec] = std::from_chars(begin, end, index);
  if (ec != std::errc() || ptr != end || begin == end || index < low || index >= high) {
    return std::nullopt;
  }
  return index;
}

const std::map<std::string, ValueType>& FixedOutputs() {
  static const std::map<std::string, ValueType> kOutputs = {
      {"timestamp", ValueType::kDouble},
      {"actual_q", ValueType::kVector6d},
      {"actual_qd", ValueType::kVector6d},
      {"target_q", ValueType::kVector6d},
      {"target_qd", ValueType::kVector6d},
      {"actual_TCP_pose", ValueType::kVector6d},
      {"target_TCP_pose", ValueType::kVector6d},
      {"tcp_offset", ValueType::kVector6d},
      {"robot_mode", ValueType::kInt32},
      {"safety_mode", ValueType::kInt32},
      {"safety_status_bits", ValueType::kUint32},
      {"runtime_state", ValueType::kUint32},
      {"robot_status_bits", ValueType::kUint32},
      {"speed_scaling", ValueType::kDouble},
      {"target_speed_fraction", ValueType::kDouble},
      {"joint_mode", ValueType::kVector6Int32},
      {"actual_digital_input_bits", ValueType::kUint64},
  };
  return kOutputs;
}

}  // namespace

std::optional<ValueType> OutputType(const std::string& name) {
  if (auto it = FixedOutputs().find(name); it != FixedOutputs().end()) return it->second;
  for (std::string_view side : {"input_", "output_"}) {
    const std::string base(side);
    if (RegisterIndex(name, base + "int_register_", 0, kRegisterCount)) return ValueType::kInt32;
    if (RegisterIndex(name, base + "double_register_", 0, kRegisterCount)) {
      return ValueType::kDouble;
    }
  }
  return std::nullopt;
}

std::optional<ValueType> InputType(const std::string& name) {
  if (name == "speed_slider_mask") return ValueType::kUint32;
  if (name == "speed_slider_fraction") return ValueType::kDouble;
  if (RegisterIndex(name, "input_int_register_", 0, kRegisterCount)) return ValueType::kInt32;
  if (RegisterIndex(name, "input_double_register_", 0, kRegisterCount)) return ValueType::kDouble;
  if (RegisterIndex(name, "input_bit_register_", 64, 128)) return ValueType::kBool;
  return std::nullopt;
}

Value OutputValue(const std::string& name, const ControllerState& s) {
  if (name == "timestamp") return s.timestamp;
  if (name == "actual_q") return s.actual_q;
  if (name == "actual_qd") return s.actual_qd;
  if (name == "target_q") return s.target_q;
  if (name == "target_qd") return s.target_qd;
  if (name == "actual_TCP_pose") return s.actual_tcp_pose;
  if (name == "target_TCP_pose") return s.target_tcp_pose;
  if (name == "tcp_offset") return s.tcp_offset;
  if (name == "robot_mode") return s.robot_mode;
  if (name == "safety_mode") return s.safety_mode;
  if (name == "safety_status_bits") return s.safety_status_bits;
  if (name == "runtime_state") return s.runtime_state;
  if (name == "robot_status_bits") return s.robot_status_bits;
  if (name == "speed_scaling") return s.speed_scaling;
  if (name == "target_speed_fraction") return s.target_speed_fraction;
  // Running joints report mode 253 (JOINT_RUNNING_MODE), powered-off ones 239 (POWER_OFF).
  if (name == "joint_mode") {
    const int32_t mode = s.robot_mode == 7 ? 253 : 239;
    return std::array<int32_t, 6>{mode, mode, mode, mode, mode, mode};
  }
  if (name == "actual_digital_input_bits") return uint64_t{0};
  if (auto i = RegisterIndex(name, "input_int_register_", 0, kRegisterCount)) {
    return s.input_int[*i];
  }
  if (auto i = RegisterIndex(name, "output_int_register_", 0, kRegisterCount)) {
    return s.output_int[*i];
  }
  if (auto i = RegisterIndex(name, "input_double_register_", 0, kRegisterCount)) {
    return s.input_double[*i];
  }
  if (auto i = RegisterIndex(name, "output_double_register_", 0, kRegisterCount)) {
    return s.output_double[*i];
  }
  throw std::invalid_argument("RTDE emulator: unknown output " + name);
}

void WriteInput(const std::string& name, const Value& value, ControllerState& s) {
  if (name == "speed_slider_mask") {
    s.speed_slider_mask = std::get<uint32_t>(value);
  } else if (name == "speed_slider_fraction") {
    s.speed_slider_fraction = std::get<double>(value);
  } else if (auto i = RegisterIndex(name, "input_int_register_", 0, kRegisterCount)) {
    s.input_int[*i] = std::get<int32_t>(value);
  } else if (auto j = RegisterIndex(name, "input_double_register_", 0, kRegisterCount)) {
    s.input_double[*j] = std::get<double>(value);
  } else if (auto k = RegisterIndex(name, "input_bit_register_", 64, 128)) {
    const uint64_t bit = uint64_t{1} << (*k - 64);
    s.input_bit_registers =
        std::get<bool>(value) ? (s.input_bit_registers | bit) : (s.input_bit_registers & ~bit);
  } else {
    throw std::invalid_argument("RTDE emulator: unknown input " + name);
  }
}

}  // namespace avc::sim::ur5
