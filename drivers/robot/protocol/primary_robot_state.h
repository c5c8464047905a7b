#pragma once

// The primary/secondary interface's ROBOT_STATE message (type 16, sent at 10 Hz on 30001/30002):
// a sequence of sub-packages framed like packages (int32 size incl. header, uint8 type). We
// encode ROBOT_MODE_DATA, JOINT_DATA, CARTESIAN_INFO and KINEMATICS_INFO in the CB3 3.5 layouts
// of Universal_Robots_Client_Library src/primary/robot_state/*.cpp and also decode the shorter
// 3.0-3.4 ones; decoders skip unknown sub-packages and any trailing bytes of known ones by size
// (newer software appends fields).

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace avc::robot::primary {

inline constexpr uint8_t kRobotStateType = 16;
inline constexpr uint8_t kRobotModeDataType = 0;
inline constexpr uint8_t kJointDataType = 1;
inline constexpr uint8_t kCartesianInfoType = 4;
inline constexpr uint8_t kKinematicsInfoType = 5;

// Per-joint modes (JOINT_DATA jointMode) of a CB3 (ur/datatypes.h JointMode).
inline constexpr uint8_t kJointModePowerOff = 239;
inline constexpr uint8_t kJointModeRunning = 253;
inline constexpr uint8_t kJointModeIdle = 255;

struct RobotModeData {
  uint64_t timestamp_us = 0;
  bool real_robot_connected = true;
  bool real_robot_enabled = true;
  bool power_on = false;
  bool emergency_stopped = false;
  bool protective_stopped = false;
  bool program_running = false;
  bool program_paused = false;
  int8_t robot_mode = 0;  // the RTDE robot_mode numbers (RobotMode)
  uint8_t control_mode = 0;
  double target_speed_fraction = 1;
  double speed_scaling = 1;
  double target_speed_fraction_limit = 1;  // kept when absent (CB3 3.0/3.1)
  bool operator==(const RobotModeData&) const = default;
};

struct JointData {
  std::array<double, 6> q_actual{}, q_target{}, qd_actual{};
  std::array<float, 6> current{}, voltage{}, motor_temperature{}, micro_temperature{};
  std::array<uint8_t, 6> mode{};
  bool operator==(const JointData&) const = default;
};

// The flange/TCP pose in base: x y z (m), rotation vector (rad).
struct CartesianInfo {
  std::array<double, 6> pose{};
  std::array<double, 6> tcp_offset{};
  bool operator==(const CartesianInfo&) const = default;
};

// KINEMATICS_INFO: the arm's factory-calibrated DH set.
struct KinematicsInfo {
  std::array<uint32_t, 6> checksum{};
  std::array<double, 6> theta{}, a{}, d{}, alpha{};
  uint32_t calibration_status = 0;
  bool operator==(const KinematicsInfo&) const = default;
};

// One ROBOT_STATE message: whichever sub-packages it carried.
struct RobotStateMessage {
  std::optional<RobotModeData> mode;
  std::optional<JointData> joints;
  std::optional<CartesianInfo> cartesian;
  std::optional<KinematicsInfo> kinematics;
};

// A framed ROBOT_STATE package with the sub-packages present in `state`, in type order.
std::vector<uint8_t> EncodeRobotState(const RobotStateMessage& state);
// From a ROBOT_STATE body (the bytes after the 5-byte header). Throws std::runtime_error naming
// the sub-package when a size runs past the package or a known sub-package is truncated.
RobotStateMessage DecodeRobotState(const std::vector<uint8_t>& body);

// Shorthands for the KINEMATICS_INFO-only case.
std::vector<uint8_t> EncodeKinematicsState(const KinematicsInfo& info);
std::optional<KinematicsInfo> FindKinematicsInfo(const std::vector<uint8_t>& body);

}  // namespace avc::robot::primary
