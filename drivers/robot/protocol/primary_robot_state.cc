#include "drivers/robot/protocol/primary_robot_state.h"

#include <fmt/format.h>

#include <stdexcept>

#include "drivers/robot/protocol/big_endian.h"
#include "drivers/robot/protocol/primary_protocol.h"

namespace avc::robot::primary {
namespace {

void WriteBools(BigEndianWriter& out, std::initializer_list<bool> flags) {
  for (bool flag : flags) out.U8(flag ? 1 : 0);
}

std::vector<uint8_t> EncodeMode(const RobotModeData& m) {
  BigEndianWriter out;
  out.U64(m.timestamp_us);
  WriteBools(out, {m.real_robot_connected, m.real_robot_enabled, m.power_on, m.emergency_stopped,
                   m.protective_stopped, m.program_running, m.program_paused});
  out.U8(static_cast<uint8_t>(m.robot_mode));
  out.U8(m.control_mode);
  out.F64(m.target_speed_fraction);
  out.F64(m.speed_scaling);
  out.F64(m.target_speed_fraction_limit);
  out.U8(0);  // reserved
  return FramePackage(kRobotModeDataType, out.bytes());
}

RobotModeData DecodeMode(BigEndianReader& in) {
  RobotModeData m;
  m.timestamp_us = in.U64();
  for (bool* flag :
       {&m.real_robot_connected, &m.real_robot_enabled, &m.power_on, &m.emergency_stopped,
        &m.protective_stopped, &m.program_running, &m.program_paused}) {
    *flag = in.U8() != 0;
  }
  m.robot_mode = static_cast<int8_t>(in.U8());
  m.control_mode = in.U8();
  m.target_speed_fraction = in.F64();
  m.speed_scaling = in.F64();
  // CB3 3.0/3.1 end here (38-byte sub-package); 3.2-3.4 add the limit (46), 3.5 and later a
  // reserved byte (47) (python-urx ursecmon.py; fixture robot_state_cb3_3_0_layout_mode_38).
  if (in.Remaining() >= sizeof(double)) m.target_speed_fraction_limit = in.F64();
  return m;
}

std::vector<uint8_t> EncodeJoints(const JointData& j) {
  BigEndianWriter out;
  for (int i = 0; i < 6; ++i) {
    out.F64(j.q_actual[i]);
    out.F64(j.q_target[i]);
    out.F64(j.qd_actual[i]);
    out.F32(j.current[i]);
    out.F32(j.voltage[i]);
    out.F32(j.motor_temperature[i]);
    out.F32(j.micro_temperature[i]);
    out.U8(j.mode[i]);
  }
  return FramePackage(kJointDataType, out.bytes());
}

JointData DecodeJoints(BigEndianReader& in) {
  JointData j;
  for (int i = 0; i < 6; ++i) {
    j.q_actual[i] = in.F64();
    j.q_target[i] = in.F64();
    j.qd_actual[i] = in.F64();
    j.current[i] = in.F32();
    j.voltage[i] = in.F32();
    j.motor_temperature[i] = in.F32();
    j.micro_temperature[i] = in.F32();
    j.mode[i] = in.U8();
  }
  return j;
}

std::vector<uint8_t> EncodeCartesian(const CartesianInfo& c) {
  BigEndianWriter out;
  for (double v : c.pose) out.F64(v);
  for (double v : c.tcp_offset) out.F64(v);
  return FramePackage(kCartesianInfoType, out.bytes());
}

CartesianInfo DecodeCartesian(BigEndianReader& in) {
  CartesianInfo c;
  for (double& v : c.pose) v = in.F64();
  // Older software sends the pose only.
  if (in.Remaining() >= 6 * sizeof(double)) {
    for (double& v : c.tcp_offset) v = in.F64();
  }
  return c;
}

std::vector<uint8_t> EncodeKinematics(const KinematicsInfo& info) {
  BigEndianWriter out;
  for (uint32_t c : info.checksum) out.U32(c);
  for (const auto* values : {&info.theta, &info.a, &info.d, &info.alpha}) {
    for (double v : *values) out.F64(v);
  }
  out.U32(info.calibration_status);
  return FramePackage(kKinematicsInfoType, out.bytes());
}

KinematicsInfo DecodeKinematics(BigEndianReader& in) {
  KinematicsInfo info;
  for (auto& c : info.checksum) c = in.U32();
  for (auto* values : {&info.theta, &info.a, &info.d, &info.alpha}) {
    for (double& v : *values) v = in.F64();
  }
  info.calibration_status = in.U32();
  return info;
}

void Append(std::vector<uint8_t>& body, const std::vector<uint8_t>& sub) {
  body.insert(body.end(), sub.begin(), sub.end());
}

}  // namespace

std::vector<uint8_t> EncodeRobotState(const RobotStateMessage& state) {
  std::vector<uint8_t> body;
  if (state.mode) Append(body, EncodeMode(*state.mode));
  if (state.joints) Append(body, EncodeJoints(*state.joints));
  if (state.cartesian) Append(body, EncodeCartesian(*state.cartesian));
  if (state.kinematics) Append(body, EncodeKinematics(*state.kinematics));
  return FramePackage(kRobotStateType, body);
}

RobotStateMessage DecodeRobotState(const std::vector<uint8_t>& body) {
  RobotStateMessage state;
  size_t offset = 0;
  while (offset + kHeaderSize <= body.size()) {
    BigEndianReader header(body.data() + offset, body.size() - offset, "ROBOT_STATE sub-package");
    const uint32_t size = header.U32();
    const uint8_t type = header.U8();
    if (size < kHeaderSize || size > body.size() - offset) {
      throw std::runtime_error(fmt::format(
          "ROBOT_STATE sub-package {} at offset {} announces {} bytes", type, offset, size));
    }
    const uint8_t* data = body.data() + offset + kHeaderSize;
    const size_t length = size - kHeaderSize;
    switch (type) {
      case kRobotModeDataType: {
        BigEndianReader in(data, length, "ROBOT_MODE_DATA");
        state.mode = DecodeMode(in);
        break;
      }
      case kJointDataType: {
        BigEndianReader in(data, length, "JOINT_DATA");
        state.joints = DecodeJoints(in);
        break;
      }
      case kCartesianInfoType: {
        BigEndianReader in(data, length, "CARTESIAN_INFO");
        state.cartesian = DecodeCartesian(in);
        break;
      }
      case kKinematicsInfoType: {
        BigEndianReader in(data, length, "KINEMATICS_INFO");
        state.kinematics = DecodeKinematics(in);
        break;
      }
      default:
        break;  // skipped by size
    }
    offset += size;
  }
  return state;
}

std::vector<uint8_t> EncodeKinematicsState(const KinematicsInfo& info) {
  RobotStateMessage state;
  state.kinematics = info;
  return EncodeRobotState(state);
}

std::optional<KinematicsInfo> FindKinematicsInfo(const std::vector<uint8_t>& body) {
  return DecodeRobotState(body).kinematics;
}

}  // namespace avc::robot::primary
