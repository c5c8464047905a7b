// RobotNode's command side: robot_command_t in, ack_t and the controller calls out, and
// robot_state_t publication. The connection, polling and watchdog side is in robot_node.cc.

#include <fmt/format.h>

#include <algorithm>
#include <avc/robot_state_t.hpp>
#include <cmath>

#include "core/bus/channels.h"
#include "core/kinematics/row_major_pose.h"
#include "core/util/log.h"
#include "drivers/robot/plant_keep_out_command.h"
#include "drivers/robot/robot_node.h"
#include "drivers/robot/urscript.h"

namespace avc::robot {
namespace {

using Command = avc::robot_command_t;
using kinematics::IsometryFromRowMajor;
using kinematics::JointVector;
using kinematics::RowMajorFromIsometry;
using Clock = std::chrono::steady_clock;

JointVector ToJoints(const std::array<double, 6>& q) {
  return Eigen::Map<const JointVector>(q.data());
}

}  // namespace

void RobotNode::Ack(const std::string& request_id, int8_t status, const std::string& reason) {
  acks_.Send(request_id, status, reason);
}

bool RobotNode::Authentic(const Command& command) {
  const bool stops = command.kind == Command::KIND_STOP || command.kind == Command::KIND_POWER_OFF;
  const std::string why = verifier_->Check(command, /*signature_optional=*/stops);
  if (why.empty()) return true;
  log::Warn("{}: rejected command '{}' (kind {}): {}", config_.service, command.request_id,
            command.kind, why);
  // Not remembered: a forged or replayed copy must not become the genuine request's answer.
  acks_.SendUnremembered(command.request_id, avc::ack_t::STATUS_REFUSED, "authentication: " + why);
  return false;
}

void RobotNode::Handle(const Command& command) {
  if (command.request_id.empty()) {
    Ack("", avc::ack_t::STATUS_REFUSED, "robot command without a request id");
    return;
  }
  if (!Authentic(command)) return;
  if (acks_.Repeat(command.request_id)) return;  // idempotent: the last answer, nothing else
  if (!link_.connected()) {
    acks_.SendNotReady(command.request_id, error_);
    return;
  }
  std::string refusal;
  switch (command.kind) {
    case Command::KIND_MOVE_JOINTS:
    case Command::KIND_MOVE_LINEAR:
      if (const std::string not_ready = MotionNotReady(); !not_ready.empty()) {
        acks_.SendNotReady(command.request_id, not_ready);
        return;
      }
      refusal = StartMotion(command);
      if (refusal.empty()) {
        Ack(command.request_id, avc::ack_t::STATUS_ACCEPTED, "motion sent");
        UpdateHeartbeat();
        return;
      }
      break;
    case Command::KIND_STOP:
      Stop(command);
      return;
    case Command::KIND_SET_PLANT_KEEP_OUT:
      refusal = SetPlantKeepOut(command);
      if (refusal.empty()) {
        Ack(command.request_id, avc::ack_t::STATUS_DONE,
            config_.envelope.plant_keep_out.empty() ? "plant keep-out cleared"
                                                    : "plant keep-out set");
        return;
      }
      break;
    case Command::KIND_POWER_ON:
    case Command::KIND_BRAKE_RELEASE:
    case Command::KIND_UNLOCK_PROTECTIVE_STOP:
    case Command::KIND_POWER_OFF: {
      const std::string failure = RunDashboard(command);
      if (!failure.empty()) {
        Ack(command.request_id, avc::ack_t::STATUS_FAILED, failure);
      } else {
        StartModeChange(command);
      }
      return;
    }
    default:
      refusal = fmt::format("unknown command kind {}", command.kind);
  }
  Ack(command.request_id, avc::ack_t::STATUS_REFUSED, refusal);
}

void RobotNode::Stop(const Command& command) {
  try {
    link_.script().Send(StopJProgram(config_.stop_deceleration));
  } catch (const net::ConnectionError& error) {
    ControllerLost(error.what());
    Ack(command.request_id, avc::ack_t::STATUS_FAILED, error_);
    return;
  }
  if (active_) Finish(avc::ack_t::STATUS_FAILED, "stopped by request " + command.request_id);
  Ack(command.request_id, avc::ack_t::STATUS_DONE, "stopj sent");
}

std::string RobotNode::SetPlantKeepOut(const Command& command) {
  kinematics::PlantKeepOut keep_out = PlantKeepOutOf(command);
  if (keep_out.empty()) {
    config_.envelope.plant_keep_out = {};
    log::Info("{}: plant keep-out cleared by '{}'", config_.service, command.request_id);
    return {};
  }
  if (auto error = keep_out.Validate(); !error.empty()) return error;
  log::Info(
      "{}: plant keep-out from '{}': {} slabs of {:.3f} m from z {:.3f} m (table frame), "
      "widest {:.3f} m",
      config_.service, command.request_id, keep_out.radius_m.size(), keep_out.slab_m, keep_out.z0_m,
      *std::max_element(keep_out.radius_m.begin(), keep_out.radius_m.end()));
  config_.envelope.plant_keep_out = std::move(keep_out);
  return {};
}

std::string RobotNode::MotionNotReady() const {
  if (active_) return "busy with request " + active_->request_id;
  if (!last_state_) return "no robot state received yet";
  return {};
}

std::string RobotNode::StartMotion(const Command& command) {
  const RobotState& state = *last_state_;
  if (state.robot_mode != RobotMode::kRunning) {
    return fmt::format("robot mode is {}, not RUNNING", RobotModeName(state.robot_mode));
  }
  if (state.safety_mode != SafetyMode::kNormal) {
    return fmt::format("safety mode is {}", SafetyModeName(state.safety_mode));
  }
  const auto now = Clock::now();
  const bool watched = watchdog_.ShouldWatch(now);
  if (watched) {
    // No point starting what the watchdog would stop at the next poll.
    if (auto problem = watchdog_.Problem(now); !problem.empty()) {
      return problem + "; motion not started";
    }
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
    refusal = kinematics::CheckJointMove(config_.envelope, config_.dh, current, target, speed,
                                         acceleration);
    if (refusal.empty()) {
      const Joints q = {target[0], target[1], target[2], target[3], target[4], target[5]};
      program = MoveJProgram(q, acceleration, speed);
      monitor = MotionMonitor::ForJoints(q, config_.tolerance);
    }
  } else {
    const Eigen::Isometry3d target = IsometryFromRowMajor(command.T_base_flange);
    refusal = kinematics::CheckLinearMove(config_.envelope, config_.dh, current, target, speed,
                                          acceleration);
    if (refusal.empty()) {
      const PoseVector pose = VectorFromPose(target);
      program = MoveLProgram(pose, acceleration, speed);
      monitor = MotionMonitor::ForPose(pose, config_.tolerance);
    }
  }
  if (!refusal.empty()) return "outside the safety envelope: " + refusal;
  try {
    link_.script().Send(program);
  } catch (const net::ConnectionError& error) {
    ControllerLost(error.what());
    return error_;
  }
  if (!watched && watchdog_.enabled() && !unwatched_logged_) {
    log::Info("{}: {} not heard in the last 5 s; motions run without its heartbeat watchdog",
              config_.service, watchdog_.service());
    unwatched_logged_ = true;
  }
  active_ = ActiveMotion{command.request_id, *monitor, now + config_.motion_timeout, 0, watched};
  return {};
}

std::string RobotNode::RunDashboard(const Command& command) {
  try {
    DashboardClient& dashboard = link_.dashboard();
    switch (command.kind) {
      case Command::KIND_POWER_ON:
        dashboard.PowerOn();
        break;
      case Command::KIND_BRAKE_RELEASE:
        dashboard.BrakeRelease();
        break;
      case Command::KIND_UNLOCK_PROTECTIVE_STOP:
        dashboard.UnlockProtectiveStop();
        break;
      default:
        dashboard.PowerOff();
        break;
    }
  } catch (const net::ConnectionError& error) {
    ControllerLost(error.what());
    return error_;
  } catch (const std::exception& error) {
    return error.what();
  }
  return {};
}

namespace {

// Whether the controller reached what a dashboard command asks for, and how that reads.
bool ModeReached(int8_t kind, const RobotState& state) {
  switch (kind) {
    case avc::robot_command_t::KIND_POWER_ON:
      return state.robot_mode == RobotMode::kIdle || state.robot_mode == RobotMode::kRunning;
    case avc::robot_command_t::KIND_BRAKE_RELEASE:
      return state.robot_mode == RobotMode::kRunning;
    case avc::robot_command_t::KIND_UNLOCK_PROTECTIVE_STOP:
      return state.safety_mode == SafetyMode::kNormal;
    default:
      return state.robot_mode == RobotMode::kPowerOff;
  }
}

}  // namespace

void RobotNode::StartModeChange(const avc::robot_command_t& command) {
  if (mode_change_)
    FinishModeChange(avc::ack_t::STATUS_FAILED, "superseded by " + command.request_id);
  Ack(command.request_id, avc::ack_t::STATUS_ACCEPTED, "dashboard command sent");
  mode_change_ =
      ModeChange{command.request_id, command.kind, Clock::now() + config_.mode_change_timeout};
  CheckModeChange();
}

void RobotNode::CheckModeChange() {
  if (!mode_change_ || !last_state_) return;
  if (ModeReached(mode_change_->kind, *last_state_)) {
    FinishModeChange(
        avc::ack_t::STATUS_DONE,
        fmt::format("robot mode {}, safety mode {}", RobotModeName(last_state_->robot_mode),
                    SafetyModeName(last_state_->safety_mode)));
  } else if (Clock::now() > mode_change_->deadline) {
    FinishModeChange(
        avc::ack_t::STATUS_FAILED,
        fmt::format("controller still in robot mode {}, safety mode {} after {} ms",
                    RobotModeName(last_state_->robot_mode),
                    SafetyModeName(last_state_->safety_mode), config_.mode_change_timeout.count()));
  }
}

void RobotNode::FinishModeChange(int8_t status, const std::string& reason) {
  if (!mode_change_) return;
  const std::string id = mode_change_->request_id;
  mode_change_.reset();
  Ack(id, status, reason);
}

void RobotNode::Finish(int8_t status, std::string reason) {
  const std::string request_id = active_->request_id;
  active_.reset();
  Ack(request_id, status, reason);
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
