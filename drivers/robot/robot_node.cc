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

using Clock = std::chrono::steady_clock;

// Consecutive "reached" states required, so one state from before the program started (already
// at the target by chance) cannot end the motion early.
constexpr int kSettleSamples = 3;

ControllerAddress AddressOf(const RobotNodeConfig& config) {
  return {config.host, config.rtde_port, config.secondary_port, config.dashboard_port,
          config.connect_timeout};
}

}  // namespace

std::string RobotNodeConfig::Validate() const {
  if (service.empty()) return "empty service name";
  if (connect_timeout.count() <= 0) return "connect timeout must be > 0";
  if (poll_period.count() <= 0) return "poll period must be > 0";
  if (reconnect_min.count() <= 0 || reconnect_max < reconnect_min) {
    return "reconnect backoff must satisfy 0 < min <= max";
  }
  if (watchdog_timeout.count() <= 0) return "watchdog timeout must be > 0";
  if (!(stop_deceleration > 0 && std::isfinite(stop_deceleration))) {
    return fmt::format("stop deceleration {} must be > 0", stop_deceleration);
  }
  if (!(state_rate_hz > 0 && std::isfinite(state_rate_hz))) {
    return fmt::format("state rate {} Hz must be > 0", state_rate_hz);
  }
  if (auto error = envelope.Validate(); !error.empty()) return "safety envelope: " + error;
  if (auto error = auth.Validate(); !error.empty()) return error;
  return {};
}

RobotNode::RobotNode(bus::Bus& bus, bus::EventLoop& loop, bus::HeartbeatPublisher& heartbeat,
                     RobotNodeConfig config)
    : bus_(bus),
      loop_(loop),
      heartbeat_(heartbeat),
      config_(std::move(config)),
      acks_(bus, config_.service),
      link_(AddressOf(config_)),
      watchdog_(config_.watchdog_service, config_.watchdog_timeout),
      reconnect_delay_(config_.reconnect_min) {
  if (auto error = config_.Validate(); !error.empty()) {
    throw std::invalid_argument("avc-robot config: " + error);
  }
  verifier_.emplace(config_.auth, bus_.FullChannel(channels::kRobotCommand), bus_.cell());
  verifier_->LogStartup(config_.service);
  command_subscription_ = bus_.Subscribe<avc::robot_command_t>(
      channels::kRobotCommand,
      [this](const avc::robot_command_t& command, const bus::RxInfo&) { Handle(command); });
  heartbeat_subscription_ = bus_.Subscribe<avc::heartbeat_t>(
      channels::kHeartbeat,
      [this](const avc::heartbeat_t& beat, const bus::RxInfo&) { OnHeartbeat(beat); });
  TryConnect();
  UpdateHeartbeat();
  timer_ = loop_.AddTimer(
      config_.poll_period, [this] { Tick(); }, /*repeating=*/true);
}

RobotNode::~RobotNode() {
  if (timer_ != 0) loop_.CancelTimer(timer_);
  bus_.Unsubscribe(heartbeat_subscription_);
  bus_.Unsubscribe(command_subscription_);
}

void RobotNode::TryConnect() {
  try {
    link_.Connect();
  } catch (const std::exception& error) {
    ControllerLost(error.what());
    return;
  }
  error_.clear();
  reconnect_delay_ = config_.reconnect_min;
  log::Info("{}: connected to the controller at {}", config_.service, config_.host);
  LogControllerKinematics();
}

void RobotNode::ControllerLost(const std::string& what) {
  link_.Disconnect();
  last_state_.reset();  // a stale state must not plan the next motion
  error_ =
      fmt::format("controller lost: {}; reconnecting in {} ms", what, reconnect_delay_.count());
  next_connect_ = Clock::now() + reconnect_delay_;
  reconnect_delay_ = std::min(reconnect_delay_ * 2, config_.reconnect_max);
  // The heartbeat publisher logs the ERROR it announces.
  if (active_) Finish(avc::ack_t::STATUS_FAILED, "controller lost: " + what);
  FinishModeChange(avc::ack_t::STATUS_FAILED, "controller lost: " + what);
}

void RobotNode::Tick() {
  if (!link_.connected()) {
    if (Clock::now() >= next_connect_) TryConnect();
  } else {
    try {
      link_.CheckDashboard();
      Poll();
      CheckWatchdog();
    } catch (const std::exception& error) {
      // A broken or corrupt stream cannot be resynchronised: start over on every interface.
      ControllerLost(error.what());
    }
  }
  UpdateHeartbeat();
}

void RobotNode::UpdateHeartbeat() {
  if (shut_down_) return;  // the runtime says STOPPING now
  if (!error_.empty()) {
    heartbeat_.Set(bus::ServiceState::kError, error_);
  } else if (active_) {
    heartbeat_.Set(bus::ServiceState::kBusy, "moving: " + active_->request_id);
  } else if (!last_state_) {
    // READY promises a motion can start: not before the controller's first state.
    heartbeat_.Set(bus::ServiceState::kStarting,
                   "connected to " + config_.host + "; waiting for its first state");
  } else {
    heartbeat_.Set(bus::ServiceState::kReady, "connected to " + config_.host);
  }
}

void RobotNode::OnHeartbeat(const avc::heartbeat_t& beat) {
  if (beat.service != watchdog_.service() || !watchdog_.enabled()) return;
  const bool healthy =
      beat.state != avc::heartbeat_t::STATE_STOPPING && beat.state != avc::heartbeat_t::STATE_ERROR;
  watchdog_.Heard(Clock::now(), healthy, bus::ServiceStateName(beat.state));
  unwatched_logged_ = false;
}

void RobotNode::CheckWatchdog() {
  if (!active_ || !active_->watched) return;
  const std::string reason = watchdog_.StopReason(Clock::now());
  if (reason.empty()) return;
  link_.script().Send(StopJProgram(config_.stop_deceleration));
  log::Error("{}: {} (request {})", config_.service, reason, active_->request_id);
  Finish(avc::ack_t::STATUS_FAILED, reason);
}

void RobotNode::LogControllerKinematics() {
  // The controller's calibrated DH set, logged at every connect so a scan's log records which
  // arm it was; poses for calibration come from actual_TCP_pose, which already includes it.
  const auto& kinematics = link_.kinematics();
  if (!kinematics) {
    log::Warn("{}: no KINEMATICS_INFO from {} within {} ms", config_.service, link_.script().peer(),
              config_.connect_timeout.count());
    return;
  }
  double largest_length_delta = 0;
  for (int i = 0; i < 6; ++i) {
    largest_length_delta =
        std::max({largest_length_delta, std::abs(kinematics->a[i] - config_.dh.a[i]),
                  std::abs(kinematics->d[i] - config_.dh.d[i])});
  }
  log::Info(
      "{}: controller kinematics a=[{:.6f}] d=[{:.6f}] (largest length delta from nominal {:.6f} "
      "m)",
      config_.service, fmt::join(kinematics->a, ", "), fmt::join(kinematics->d, ", "),
      largest_length_delta);
}

void RobotNode::Poll() {
  for (const auto& message : link_.script().Poll(net::Milliseconds(0))) {
    if (active_ && message.message_type == primary::kRuntimeException) {
      Finish(avc::ack_t::STATUS_FAILED, "controller runtime error: " + message.text);
    }
  }
  while (auto sample = link_.rtde().Receive(net::Milliseconds(0))) {
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
  CheckModeChange();
  if (active_ && Clock::now() > active_->deadline) {
    Finish(avc::ack_t::STATUS_FAILED,
           fmt::format("motion not finished within {} ms: {}", config_.motion_timeout.count(),
                       active_->monitor.detail()));
  }
}

void RobotNode::Shutdown() {
  if (timer_ != 0) loop_.CancelTimer(timer_);
  timer_ = 0;
  if (active_ && link_.connected()) {
    try {
      link_.script().Send(StopJProgram(config_.stop_deceleration));
      log::Info("{}: arm stopped for shutdown", config_.service);
    } catch (const std::exception& error) {
      log::Error("{}: could not stop the arm at shutdown: {}", config_.service, error.what());
    }
  }
  if (active_) Finish(avc::ack_t::STATUS_FAILED, config_.service + " stopping");
  FinishModeChange(avc::ack_t::STATUS_FAILED, config_.service + " stopping");
  link_.Disconnect();
  shut_down_ = true;
  error_ = config_.service + " stopping";
}

}  // namespace avc::robot
