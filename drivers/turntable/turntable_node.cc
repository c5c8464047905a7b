#include "drivers/turntable/turntable_node.h"

#include <fmt/format.h>

#include <algorithm>
#include <avc/turntable_state_t.hpp>
#include <cmath>
#include <numbers>
#include <utility>

#include "core/bus/channels.h"
#include "core/util/log.h"

namespace avc::turntable {
namespace {

constexpr double kDegPerRad = 180 / std::numbers::pi;

class MonotonicClock final : public Clock {
 public:
  int64_t NowMicros() const override { return MonotonicMicros(); }
};

const char* KindName(int8_t kind) {
  switch (kind) {
    case avc::turntable_command_t::KIND_GOTO:
      return "goto";
    case avc::turntable_command_t::KIND_STEP:
      return "step";
    case avc::turntable_command_t::KIND_HOME:
      return "home";
    case avc::turntable_command_t::KIND_STOP:
      return "stop";
    default:
      return "unknown";
  }
}

// Radians to whole tenths of a degree (the table's resolution).
int RadToTenths(double rad) { return static_cast<int>(std::lround(rad * kDegPerRad * 10)); }

}  // namespace

std::string TurntableNodeOptions::Validate() const {
  if (device.empty()) return "no turntable device given";
  if (poll_period.count() <= 0) return "poll period must be > 0";
  if (reconnect_min.count() <= 0 || reconnect_max < reconnect_min) {
    return "reconnect backoff must satisfy 0 < min <= max";
  }
  if (failures_before_reconnect < 1) return "failures before reconnect must be >= 1";
  const std::string table = device_options.table.Validate();
  if (!table.empty()) return table;
  if (std::string problem = auth.Validate(); !problem.empty()) return problem;
  return controller.Validate();
}

TurntableNode::TurntableNode(bus::Bus& bus, bus::EventLoop& loop,
                             bus::HeartbeatPublisher& heartbeat, TurntableNodeOptions options)
    : bus_(bus),
      loop_(loop),
      heartbeat_(heartbeat),
      options_(std::move(options)),
      acks_(bus, options_.service),
      clock_(std::make_unique<MonotonicClock>()),
      reconnect_delay_(options_.reconnect_min) {
  const std::string problem = options_.Validate();
  if (!problem.empty()) throw std::invalid_argument("avc-turntable: " + problem);
  verifier_.emplace(options_.auth, bus_.FullChannel(channels::kTurntableCommand), bus_.cell());
  verifier_->LogStartup(options_.service);
  subscription_ = bus_.Subscribe<avc::turntable_command_t>(
      channels::kTurntableCommand,
      [this](const avc::turntable_command_t& command, const bus::RxInfo&) { OnCommand(command); });
  TryConnect();
  UpdateHeartbeat();
  PublishState();
  timer_ = loop_.AddTimer(
      options_.poll_period, [this] { Tick(); }, /*repeating=*/true);
}

TurntableNode::~TurntableNode() {
  loop_.CancelTimer(timer_);
  bus_.Unsubscribe(subscription_);
}

void TurntableNode::TryConnect() {
  try {
    auto port = std::make_unique<SerialPort>(options_.device, options_.baud);
    auto device = std::make_unique<Lt360Device>(std::move(port), options_.device_options);
    auto controller = std::make_unique<TurntableController>(*device, options_.controller, *clock_);
    controller->Poll();  // the device must answer before we call it connected
    device_ = std::move(device);
    controller_ = std::move(controller);
    error_.clear();
    consecutive_failures_ = 0;
    reconnect_delay_ = options_.reconnect_min;
    log::Info("turntable connected on {} at {:.1f} deg", options_.device,
              controller_->last_reading().position_tenths / 10.0);
  } catch (const std::exception& e) {
    error_ = fmt::format("cannot connect to the turntable on {}: {} (retry in {} ms)",
                         options_.device, e.what(), reconnect_delay_.count());
    log::Warn("{}", error_);
    next_connect_us_ = MonotonicMicros() + reconnect_delay_.count() * 1000;
    reconnect_delay_ = std::min(reconnect_delay_ * 2, options_.reconnect_max);
  }
}

void TurntableNode::Disconnect(const std::string& why) {
  controller_.reset();
  device_.reset();
  FinishActive(avc::ack_t::STATUS_FAILED, "turntable lost: " + why);
  error_ = "turntable lost: " + why;
  log::Error("{}", error_);
  next_connect_us_ = MonotonicMicros() + reconnect_delay_.count() * 1000;
}

void TurntableNode::DeviceFailed(const std::exception& error) {
  error_ = error.what();
  if (dynamic_cast<const SerialError*>(&error) != nullptr ||
      ++consecutive_failures_ >= options_.failures_before_reconnect) {
    Disconnect(error.what());
    return;
  }
  log::Warn("turntable: {} (recovering)", error_);
}

void TurntableNode::Tick() {
  if (!device_) {
    if (MonotonicMicros() >= next_connect_us_) TryConnect();
  } else {
    try {
      const MoveReport report = controller_->Poll();
      error_.clear();
      consecutive_failures_ = 0;
      if (report.result == MoveResult::kDone) {
        FinishActive(avc::ack_t::STATUS_DONE, report.detail);
      } else if (report.result == MoveResult::kFailed) {
        FinishActive(avc::ack_t::STATUS_FAILED, report.detail);
      }
    } catch (const std::exception& e) {
      // The next poll flushes and re-queries: that is the recovery.
      DeviceFailed(e);
    }
  }
  UpdateHeartbeat();
  PublishState();
}

std::string TurntableNode::Validate(const avc::turntable_command_t& command) const {
  if (command.request_id.empty()) return "empty request_id";
  switch (command.kind) {
    case avc::turntable_command_t::KIND_GOTO:
    case avc::turntable_command_t::KIND_STEP:
      if (!std::isfinite(command.angle)) {
        return fmt::format("{} angle must be finite, got {}", KindName(command.kind),
                           command.angle);
      }
      if (command.kind == avc::turntable_command_t::KIND_STEP &&
          std::abs(command.angle) > 2 * std::numbers::pi) {
        return fmt::format("step of {} rad exceeds one turn", command.angle);
      }
      // A goto is taken modulo one turn, but only after rounding to tenths of a degree in an
      // int: an angle of 1e20 rad would overflow there and land anywhere.
      if (command.kind == avc::turntable_command_t::KIND_GOTO &&
          std::abs(command.angle) > 4 * std::numbers::pi) {
        return fmt::format("goto {} rad is beyond two turns either way", command.angle);
      }
      break;
    case avc::turntable_command_t::KIND_HOME:
    case avc::turntable_command_t::KIND_STOP:
      break;
    default:
      return fmt::format("unknown command kind {}", command.kind);
  }
  if (!std::isfinite(command.speed) || command.speed < 0) {
    return fmt::format("speed must be >= 0 rad/s (0 = default), got {}", command.speed);
  }
  return "";
}

std::string TurntableNode::NotReady(const avc::turntable_command_t& command) const {
  if (!device_) return "turntable not connected: " + error_;
  if (!active_request_.empty() && command.kind != avc::turntable_command_t::KIND_STOP) {
    return fmt::format("busy with request '{}' ({})", active_request_, active_description_);
  }
  return "";
}

bool TurntableNode::Authentic(const avc::turntable_command_t& command) {
  const bool stop = command.kind == avc::turntable_command_t::KIND_STOP;
  const std::string why = verifier_->Check(command, /*signature_optional=*/stop);
  if (why.empty()) return true;
  log::Warn("turntable: rejected {} '{}': {}", KindName(command.kind), command.request_id, why);
  // Not remembered: a forged or replayed copy must not become the genuine request's answer.
  acks_.SendUnremembered(command.request_id, avc::ack_t::STATUS_REFUSED, "authentication: " + why);
  return false;
}

void TurntableNode::OnCommand(const avc::turntable_command_t& command) {
  if (!Authentic(command)) return;
  if (acks_.Repeat(command.request_id)) return;  // answered before: never move again
  const std::string refusal = Validate(command);
  if (!refusal.empty()) {
    log::Warn("turntable: refused {} '{}': {}", KindName(command.kind), command.request_id,
              refusal);
    SendAck(command.request_id, avc::ack_t::STATUS_REFUSED, refusal);
    return;
  }
  if (const std::string not_ready = NotReady(command); !not_ready.empty()) {
    acks_.SendNotReady(command.request_id, not_ready);
    return;
  }
  if (command.kind == avc::turntable_command_t::KIND_STOP) {
    Stop(command);
  } else {
    Start(command);
  }
  UpdateHeartbeat();
  PublishState();
}

void TurntableNode::Start(const avc::turntable_command_t& command) {
  const double speed_deg_s = command.speed * kDegPerRad;
  try {
    switch (command.kind) {
      case avc::turntable_command_t::KIND_GOTO: {
        const int target = NormaliseTenths(RadToTenths(command.angle));
        active_description_ = fmt::format("goto {:.1f} deg", target / 10.0);
        controller_->StartGoto(target, Direction::kShortest, speed_deg_s);
        break;
      }
      case avc::turntable_command_t::KIND_STEP: {
        const int delta = RadToTenths(command.angle);
        active_description_ = fmt::format("step {:+.1f} deg", delta / 10.0);
        controller_->StartStep(delta, speed_deg_s);
        break;
      }
      default:
        active_description_ = "home";
        controller_->StartHome(speed_deg_s);
        break;
    }
  } catch (const std::exception& e) {
    SendAck(command.request_id, avc::ack_t::STATUS_ACCEPTED, active_description_);
    SendAck(command.request_id, avc::ack_t::STATUS_FAILED, e.what());
    DeviceFailed(e);
    return;
  }
  active_request_ = command.request_id;
  log::Info("turntable: {} '{}'", active_description_, active_request_);
  SendAck(command.request_id, avc::ack_t::STATUS_ACCEPTED, active_description_);
}

void TurntableNode::Stop(const avc::turntable_command_t& command) {
  SendAck(command.request_id, avc::ack_t::STATUS_ACCEPTED, "stop");
  try {
    controller_->Stop();
  } catch (const std::exception& e) {
    SendAck(command.request_id, avc::ack_t::STATUS_FAILED, e.what());
    DeviceFailed(e);
    return;
  }
  FinishActive(avc::ack_t::STATUS_FAILED, "stopped by request '" + command.request_id + "'");
  SendAck(command.request_id, avc::ack_t::STATUS_DONE, "stopped");
}

void TurntableNode::FinishActive(int8_t status, const std::string& reason) {
  if (active_request_.empty()) return;
  const std::string id = std::exchange(active_request_, "");
  active_description_.clear();
  if (status == avc::ack_t::STATUS_FAILED) {
    log::Warn("turntable: '{}' failed: {}", id, reason);
  }
  SendAck(id, status, reason);
}

void TurntableNode::SendAck(const std::string& request_id, int8_t status,
                            const std::string& reason) {
  acks_.Send(request_id, status, reason);
}

void TurntableNode::PublishState() {
  avc::turntable_state_t state{};
  state.connected = device_ != nullptr;
  if (controller_) {
    const TableReading& reading = controller_->last_reading();
    state.angle = NormaliseTenths(reading.position_tenths) / 10.0 / kDegPerRad;
    state.moving = reading.motion != Motion::kNone || controller_->move_active();
    state.homed = controller_->homed();
  }
  state.active_request_id = active_request_;
  state.detail = !error_.empty()           ? error_
                 : active_request_.empty() ? std::string("idle")
                                           : active_description_;
  bus_.Publish(channels::kTurntableState, state);
}

void TurntableNode::UpdateHeartbeat() {
  if (!device_ || !error_.empty()) {
    heartbeat_.Set(bus::ServiceState::kError, error_);
  } else if (!active_request_.empty()) {
    heartbeat_.Set(bus::ServiceState::kBusy, active_description_);
  } else {
    heartbeat_.Set(
        bus::ServiceState::kReady,
        fmt::format("at {:.1f} deg on {}", controller_->last_reading().position_tenths / 10.0,
                    options_.device));
  }
}

void TurntableNode::Shutdown() {
  if (controller_ &&
      (controller_->move_active() || controller_->last_reading().motion != Motion::kNone)) {
    try {
      controller_->Stop();
      log::Info("turntable stopped for shutdown");
    } catch (const std::exception& e) {
      log::Error("turntable: could not stop the table at shutdown: {}", e.what());
    }
  }
  FinishActive(avc::ack_t::STATUS_FAILED, "avc-turntable stopping");
  PublishState();
}

}  // namespace avc::turntable
