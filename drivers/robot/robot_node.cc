#include "drivers/robot/robot_node.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <avc/robot_state_t.hpp>
#include <cmath>

#include "core/bus/channels.h"
#include "core/util/log.h"
#include "drivers/robot/urscript.h"

namespace avc::robot {
namespace {

using Command = avc::robot_command_t;
using Clock = std::chrono::steady_clock;

JointVector ToJoints(const std::array<double, 6>& q) {
  return Eigen::Map<const JointVector>(q.data());
}

// Consecutive "reached" states required, so one state from before the program started (already
// at the target by chance) cannot end the motion early.
constexpr int kSettleSamples = 3;

}  // namespace

Eigen::Isometry3d IsometryFromRowMajor(const double* values) {
  Eigen::Matrix4d m;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) m(r, c) = values[4 * r + c];
  }
  Eigen::Isometry3d pose;
  pose.matrix() = m;
  return pose;
}

void RowMajorFromIsometry(const Eigen::Isometry3d& pose, double* values) {
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) values[4 * r + c] = pose.matrix()(r, c);
  }
}

RobotNode::RobotNode(bus::Bus& bus, RobotNodeConfig config)
    : bus_(bus),
      config_(std::move(config)),
      rtde_(config_.host, config_.rtde_port, config_.connect_timeout),
      script_(config_.host, config_.secondary_port, config_.connect_timeout),
      dashboard_(config_.host, config_.dashboard_port, config_.connect_timeout) {
  if (auto error = config_.envelope.Validate(); !error.empty()) {
    throw std::invalid_argument("avc-robot safety envelope: " + error);
  }
  rtde_.Handshake();
  LogControllerKinematics();
  subscription_ = bus_.Subscribe<Command>(
      channels::kRobotCommand,
      [this](const Command& command, const bus::RxInfo&) { Handle(command); });
}

RobotNode::~RobotNode() { bus_.Unsubscribe(subscription_); }

void RobotNode::LogControllerKinematics() {
  // The controller's calibrated DH set, logged once so a scan's log records which arm it was;
  // poses for calibration come from actual_TCP_pose, which already includes it.
  kinematics_ = script_.WaitForKinematics(config_.connect_timeout);
  if (!kinematics_) {
    avc::log::Warn("{}: no KINEMATICS_INFO from {} within {} ms", config_.service, script_.peer(),
                   config_.connect_timeout.count());
    return;
  }
  double largest_length_delta = 0;
  for (int i = 0; i < 6; ++i) {
    largest_length_delta =
        std::max({largest_length_delta, std::abs(kinematics_->a[i] - config_.dh.a[i]),
                  std::abs(kinematics_->d[i] - config_.dh.d[i])});
  }
  avc::log::Info(
      "{}: controller kinematics a=[{:.6f}] d=[{:.6f}] (largest length delta from nominal {:.6f} "
      "m)",
      config_.service, fmt::join(kinematics_->a, ", "), fmt::join(kinematics_->d, ", "),
      largest_length_delta);
}

void RobotNode::Ack(const std::string& request_id, int8_t status, const std::string& reason) {
  avc::ack_t ack;
  ack.request_id = request_id;
  ack.service = config_.service;
  ack.status = status;
  ack.reason = reason;
  answered_[request_id] = ack;
  bus_.Publish(channels::kAck, ack);
}

void RobotNode::Handle(const Command& command) {
  if (command.request_id.empty()) {
    Ack("", avc::ack_t::STATUS_REFUSED, "robot command without a request id");
    return;
  }
  if (auto it = answered_.find(command.request_id); it != answered_.end()) {
    avc::ack_t again = it->second;  // idempotent: repeat the last answer, do nothing else
    bus_.Publish(channels::kAck, again);
    return;
  }
  std::string refusal;
  switch (command.kind) {
    case Command::KIND_MOVE_JOINTS:
    case Command::KIND_MOVE_LINEAR:
      refusal = StartMotion(command);
      if (refusal.empty()) {
        Ack(command.request_id, avc::ack_t::STATUS_ACCEPTED, "motion sent");
        return;
      }
      break;
    case Command::KIND_STOP:
      try {
        script_.Send(StopJProgram(2.0));
      } catch (const std::exception& error) {
        Ack(command.request_id, avc::ack_t::STATUS_FAILED, error.what());
        return;
      }
      if (active_) Finish(avc::ack_t::STATUS_FAILED, "stopped by request " + command.request_id);
      Ack(command.request_id, avc::ack_t::STATUS_DONE, "stopj sent");
      return;
    case Command::KIND_POWER_ON:
    case Command::KIND_BRAKE_RELEASE:
    case Command::KIND_UNLOCK_PROTECTIVE_STOP:
    case Command::KIND_POWER_OFF: {
      const std::string failure = RunDashboard(command);
      Ack(command.request_id, failure.empty() ? avc::ack_t::STATUS_DONE : avc::ack_t::STATUS_FAILED,
          failure.empty() ? "done" : failure);
      return;
    }
    default:
      refusal = fmt::format("unknown command kind {}", command.kind);
  }
  Ack(command.request_id, avc::ack_t::STATUS_REFUSED, refusal);
}

std::string RobotNode::StartMotion(const Command& command) {
  if (active_) return "busy with request " + active_->request_id;
  if (!last_state_) return "no robot state received yet";
  const RobotState& state = *last_state_;
  if (state.robot_mode != RobotMode::kRunning) {
    return fmt::format("robot mode is {}, not RUNNING", RobotModeName(state.robot_mode));
  }
  if (state.safety_mode != SafetyMode::kNormal) {
    return fmt::format("safety mode is {}", SafetyModeName(state.safety_mode));
  }
  const JointVector current = ToJoints(state.actual_q);
  const bool joints = command.kind == Command::KIND_MOVE_JOINTS;
  const double speed = command.speed != 0
                           ? command.speed
                           : (joints ? config_.default_joint_speed : config_.default_linear_speed);
  const double acceleration =
      command.acceleration != 0
          ? command.acceleration
          : (joints ? config_.default_joint_acceleration : config_.default_linear_acceleration);
  std::string refusal;
  std::string program;
  std::optional<MotionMonitor> monitor;
  if (joints) {
    const JointVector target = Eigen::Map<const JointVector>(command.q);
    refusal = CheckJointMove(config_.envelope, config_.dh, current, target, speed, acceleration);
    if (refusal.empty()) {
      const Joints q = {target[0], target[1], target[2], target[3], target[4], target[5]};
      program = MoveJProgram(q, acceleration, speed);
      monitor = MotionMonitor::ForJoints(q, config_.tolerance);
    }
  } else {
    const Eigen::Isometry3d target = IsometryFromRowMajor(command.T_base_flange);
    refusal = CheckLinearMove(config_.envelope, config_.dh, current, target, speed, acceleration);
    if (refusal.empty()) {
      const PoseVector pose = VectorFromPose(target);
      program = MoveLProgram(pose, acceleration, speed);
      monitor = MotionMonitor::ForPose(pose, config_.tolerance);
    }
  }
  if (!refusal.empty()) return "outside the safety envelope: " + refusal;
  try {
    script_.Send(program);
  } catch (const std::exception& error) {
    return error.what();
  }
  active_ = ActiveMotion{command.request_id, *monitor, Clock::now() + config_.motion_timeout, 0};
  return {};
}

std::string RobotNode::RunDashboard(const Command& command) {
  try {
    switch (command.kind) {
      case Command::KIND_POWER_ON:
        dashboard_.PowerOn();
        break;
      case Command::KIND_BRAKE_RELEASE:
        dashboard_.BrakeRelease();
        break;
      case Command::KIND_UNLOCK_PROTECTIVE_STOP:
        dashboard_.UnlockProtectiveStop();
        break;
      default:
        dashboard_.PowerOff();
        break;
    }
  } catch (const std::exception& error) {
    return error.what();
  }
  return {};
}

void RobotNode::Finish(int8_t status, std::string reason) {
  const std::string request_id = active_->request_id;
  active_.reset();
  Ack(request_id, status, reason);
}

void RobotNode::Poll() {
  try {
    for (const auto& message : script_.Poll(Milliseconds(0))) {
      if (active_ && message.message_type == primary::kRuntimeException) {
        Finish(avc::ack_t::STATUS_FAILED, "controller runtime error: " + message.text);
      }
    }
    while (auto sample = rtde_.Receive(Milliseconds(0))) {
      last_state_ = sample->state;
      if (active_) {
        const MotionStatus status = active_->monitor.Update(sample->state);
        if (status == MotionStatus::kSafetyStop || status == MotionStatus::kNotRunning) {
          Finish(avc::ack_t::STATUS_FAILED, active_->monitor.detail());
        } else if (status == MotionStatus::kReached &&
                   ++active_->reached_in_a_row >= kSettleSamples) {
          Finish(avc::ack_t::STATUS_DONE, active_->monitor.detail());
        } else if (status != MotionStatus::kReached) {
          active_->reached_in_a_row = 0;
        }
      }
      if (sample->state.timestamp - last_published_time_ >= 1.0 / config_.state_rate_hz - 1e-9) {
        PublishState(sample->state);
        last_published_time_ = sample->state.timestamp;
      }
    }
    if (active_ && Clock::now() > active_->deadline) {
      Finish(avc::ack_t::STATUS_FAILED,
             fmt::format("motion not finished within {} ms: {}", config_.motion_timeout.count(),
                         active_->monitor.detail()));
    }
  } catch (const ConnectionError& error) {
    if (active_) Finish(avc::ack_t::STATUS_FAILED, error.what());
    throw;
  }
}

void RobotNode::PublishState(const RobotState& state) {
  avc::robot_state_t message;
  for (int i = 0; i < 6; ++i) {
    message.q[i] = state.actual_q[i];
    message.qd[i] = state.actual_qd[i];
  }
  RowMajorFromIsometry(PoseFromVector(state.actual_tcp_pose), message.T_base_flange);
  message.robot_mode = static_cast<int8_t>(state.robot_mode);
  message.safety_mode = static_cast<int8_t>(state.safety_mode);
  double speed = 0;
  for (double qd : state.actual_qd) speed = std::max(speed, std::abs(qd));
  message.moving = speed > config_.tolerance.still_rad_s;
  message.protective_stop = state.safety_mode == SafetyMode::kProtectiveStop;
  message.active_request_id = active_ ? active_->request_id : "";
  bus_.Publish(channels::kRobotState, message);
}

}  // namespace avc::robot
