#include "sim/emulators/ur5/ur5_controller.h"

#include <fmt/format.h>

#include <bit>
#include <utility>

#include "core/kinematics/forward_kinematics.h"
#include "core/util/keyed_random.h"
#include "drivers/robot/protocol/ur_pose.h"

namespace avc::sim::ur5 {
namespace {

using robot::RobotMode;
using robot::SafetyMode;

// Deceleration (rad/s^2 along the path) when a new program aborts a moving one.
constexpr double kPreemptDeceleration = 4.0;
// Dashboard "stop" brakes like stopj(2).
constexpr double kDashboardStopDeceleration = 2.0;
// What a powered CB3 joint reports besides its motion (JOINT_DATA).
constexpr float kBusVoltage = 48.0f;
constexpr float kJointTemperature = 30.0f;

std::array<double, 6> ToArray(const JointVector& v) { return {v[0], v[1], v[2], v[3], v[4], v[5]}; }

// KINEMATICS_INFO of the true arm; each joint's checksum is an FNV-1a hash of its four DH
// values, so it changes exactly when that joint's calibration does.
robot::primary::KinematicsInfo KinematicsOf(const kinematics::DhParameters& dh) {
  robot::primary::KinematicsInfo info;
  for (int i = 0; i < 6; ++i) {
    info.theta[i] = dh.theta_offset[i];
    info.a[i] = dh.a[i];
    info.d[i] = dh.d[i];
    info.alpha[i] = dh.alpha[i];
    uint32_t hash = 2166136261u;
    for (double value : {dh.theta_offset[i], dh.a[i], dh.d[i], dh.alpha[i]}) {
      const auto bits = std::bit_cast<uint64_t>(value);
      for (int byte = 0; byte < 8; ++byte) {
        hash = (hash ^ static_cast<uint8_t>(bits >> (8 * byte))) * 16777619u;
      }
    }
    info.checksum[i] = hash;
  }
  info.calibration_status = 1;
  return info;
}

}  // namespace

Ur5Controller::Ur5Controller(const Ur5EmulatorOptions& options, double start_time)
    : options_(options),
      arm_(options.cell.dh, options.initial_q),
      dt_(1.0 / options.control_frequency),
      time_(start_time),
      robot_mode_(options.powered ? RobotMode::kRunning : RobotMode::kPowerOff),
      kinematics_(KinematicsOf(options.cell.dh)) {
  SampleState();
}

bool Ur5Controller::powered() const {
  return robot_mode_ == RobotMode::kPowerOn || robot_mode_ == RobotMode::kIdle ||
         robot_mode_ == RobotMode::kRunning || robot_mode_ == RobotMode::kBackdrive;
}

void Ur5Controller::RuntimeError(int session_id, int line, int column, const std::string& text) {
  robot::primary::RobotMessage message;
  message.timestamp = static_cast<uint64_t>(time_ * 1e6);
  message.message_type = robot::primary::kRuntimeException;
  message.line = line;
  message.column = column;
  message.text = text;
  messages_.push_back({session_id, robot::primary::EncodeRobotMessage(message)});
}

std::vector<SessionMessage> Ur5Controller::TakeMessages() { return std::exchange(messages_, {}); }

void Ur5Controller::RunScript(int session_id, const std::vector<std::string>& lines) {
  const ScriptProgram parsed = ParseScriptUnit(lines);
  if (parsed.error) {
    RuntimeError(session_id, parsed.error->line, parsed.error->column, parsed.error->text);
    return;
  }
  if (robot_mode_ != RobotMode::kRunning || safety_mode_ != SafetyMode::kNormal) {
    RuntimeError(session_id, 1, 1,
                 fmt::format("cannot run program: robot mode {}, safety mode {}",
                             RobotModeName(robot_mode_), SafetyModeName(safety_mode_)));
    return;
  }
  ++scripts_run_;
  // A new program aborts the running one: the arm brakes to rest (at the new program's own
  // stopj deceleration when it starts with one) before the new motions begin.
  program_ = Program{parsed.statements, 0, session_id};
  if (arm_.moving() && (parsed.statements.empty() ||
                        parsed.statements.front().kind != ScriptStatement::Kind::kStopJ)) {
    arm_.Brake(kPreemptDeceleration);
  }
  AdvanceProgram();
}

// Starts statements until one moves the arm or the program ends.
void Ur5Controller::AdvanceProgram() {
  while (program_ && program_->next < program_->statements.size()) {
    const ScriptStatement& s = program_->statements[program_->next];
    // stopj acts at once, even on a moving arm; motions wait until the arm is still.
    if (s.kind != ScriptStatement::Kind::kStopJ && arm_.moving()) break;
    ++program_->next;
    std::string error;
    switch (s.kind) {
      case ScriptStatement::Kind::kMoveJ:
        error = s.target_is_pose ? arm_.StartMoveJToPose(robot::PoseFromVector(s.target),
                                                         s.acceleration, s.velocity)
                                 : arm_.StartMoveJ(Eigen::Map<const JointVector>(s.target.data()),
                                                   s.acceleration, s.velocity);
        break;
      case ScriptStatement::Kind::kMoveL:
        error = arm_.StartMoveL(robot::PoseFromVector(s.target), s.acceleration, s.velocity);
        break;
      case ScriptStatement::Kind::kStopJ:
        arm_.Brake(s.acceleration);
        break;
    }
    if (!error.empty()) {
      RuntimeError(program_->session_id, s.line, 1, error);
      program_.reset();
      arm_.Halt();
    }
  }
  // stopj inside a program lets the arm brake to a halt before the program ends.
  if (program_ && program_->next >= program_->statements.size() && !arm_.moving()) {
    program_.reset();
  }
}

void Ur5Controller::PowerOn() {
  if (robot_mode_ == RobotMode::kPowerOff) robot_mode_ = RobotMode::kIdle;
}

void Ur5Controller::PowerOff() {
  robot_mode_ = RobotMode::kPowerOff;
  program_.reset();
  arm_.Halt();
}

void Ur5Controller::BrakeRelease() {
  if (robot_mode_ == RobotMode::kIdle) robot_mode_ = RobotMode::kRunning;
}

bool Ur5Controller::UnlockProtectiveStop() {
  if (safety_mode_ != SafetyMode::kProtectiveStop) return false;
  safety_mode_ = SafetyMode::kNormal;
  return true;
}

void Ur5Controller::StopProgram() {
  program_.reset();
  arm_.Brake(kDashboardStopDeceleration);
}

void Ur5Controller::ProtectiveStop() {
  safety_mode_ = SafetyMode::kProtectiveStop;
  arm_.Halt();
  program_.reset();
}

void Ur5Controller::Tick(double time) {
  AdvanceProgram();
  if (const std::string error = arm_.Step(dt_); !error.empty()) {
    if (program_) RuntimeError(program_->session_id, 0, 0, error);
    program_.reset();
  }
  if (stop_at_fraction_ && arm_.moving() && arm_.progress() >= *stop_at_fraction_) {
    stop_at_fraction_.reset();
    ProtectiveStop();
  }
  AdvanceProgram();
  time_ = time;
  SampleState();
}

double Ur5Controller::EncoderError(int joint, double q) const {
  const uint64_t joint_seed = util::MixSeed(options_.seed, static_cast<uint64_t>(joint));
  return util::SignedUnitFor(joint_seed, util::KeyOf(q)) * options_.encoder_noise_rad;
}

void Ur5Controller::SampleState() {
  for (int i = 0; i < 6; ++i) reported_q_[i] = arm_.q()[i] + EncoderError(i, arm_.q()[i]);
  ControllerState& s = rtde_state_;
  s.timestamp = time_;
  s.actual_q = ToArray(reported_q_);
  s.actual_qd = ToArray(arm_.qd());
  s.target_q = ToArray(arm_.target_q());
  s.target_qd = ToArray(arm_.qd());
  // The controller computes the TCP from its encoders through its own (true) kinematics.
  s.actual_tcp_pose =
      robot::VectorFromPose(kinematics::ForwardKinematics(options_.cell.dh, reported_q_));
  s.target_tcp_pose =
      robot::VectorFromPose(kinematics::ForwardKinematics(options_.cell.dh, arm_.target_q()));
  s.robot_mode = static_cast<int32_t>(robot_mode_);
  s.safety_mode = static_cast<int32_t>(safety_mode_);
  s.safety_status_bits = safety_mode_ == SafetyMode::kNormal
                             ? robot::kSafetyNormal
                             : (safety_mode_ == SafetyMode::kProtectiveStop
                                    ? (robot::kSafetyProtectiveStopped | (1u << 10))
                                    : (1u << 10));
  const bool running = program_.has_value();
  s.runtime_state = static_cast<uint32_t>(running ? robot::RuntimeState::kPlaying
                                                  : robot::RuntimeState::kStopped);
  s.robot_status_bits =
      (powered() ? robot::kStatusPowerOn : 0u) | (running ? robot::kStatusProgramRunning : 0u);
}

void Ur5Controller::WriteRtdeInput(const std::string& name, const robot::rtde::Value& value) {
  WriteInput(name, value, rtde_state_);
}

Eigen::Isometry3d Ur5Controller::TrueBaseFromFlange() const {
  return kinematics::ForwardKinematics(options_.cell.dh, arm_.q());
}

robot::primary::VersionMessage Ur5Controller::Version() const {
  return {"URControl",
          static_cast<uint8_t>(options_.version.major),
          static_cast<uint8_t>(options_.version.minor),
          static_cast<int32_t>(options_.version.bugfix),
          static_cast<int32_t>(options_.version.build),
          "emulated"};
}

robot::primary::RobotStateMessage Ur5Controller::PrimaryState() const {
  const ControllerState& s = rtde_state_;
  robot::primary::RobotModeData mode;
  mode.timestamp_us = static_cast<uint64_t>(time_ * 1e6);
  mode.power_on = powered();
  mode.protective_stopped = safety_mode_ == SafetyMode::kProtectiveStop;
  mode.program_running = program_.has_value();
  mode.robot_mode = static_cast<int8_t>(robot_mode_);
  mode.speed_scaling = s.speed_scaling;
  mode.target_speed_fraction = s.target_speed_fraction;

  robot::primary::JointData joints;
  joints.q_actual = s.actual_q;
  joints.q_target = s.target_q;
  joints.qd_actual = s.actual_qd;
  const uint8_t joint_mode = robot_mode_ == RobotMode::kRunning ? robot::primary::kJointModeRunning
                             : powered()                        ? robot::primary::kJointModeIdle
                                         : robot::primary::kJointModePowerOff;
  for (int i = 0; i < 6; ++i) {
    joints.voltage[i] = powered() ? kBusVoltage : 0.0f;
    joints.motor_temperature[i] = joints.micro_temperature[i] = kJointTemperature;
    joints.mode[i] = joint_mode;
  }

  robot::primary::RobotStateMessage state;
  state.mode = mode;
  state.joints = joints;
  state.cartesian = robot::primary::CartesianInfo{s.actual_tcp_pose, s.tcp_offset};
  state.kinematics = kinematics_;
  return state;
}

}  // namespace avc::sim::ur5
