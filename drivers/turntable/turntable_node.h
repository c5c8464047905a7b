#pragma once

// avc-turntable on the bus: maps turntable_command_t to TurntableController calls and back to
// ack_t and turntable_state_t. Everything runs on the event loop thread.
//  - Commands are answered on ACK: REFUSED (with the reason) for bad input, when busy or
//    disconnected; otherwise ACCEPTED, then DONE or FAILED. A repeated request_id re-sends the
//    last ack for it and never repeats the move. STOP ends a running move as FAILED.
//  - State goes out on TURNTABLE_STATE every poll (about 10 Hz) and at once on every change.
//  - Heartbeat: READY idle, BUSY moving, ERROR when disconnected or the device misbehaves.
//  - A device that disappears is reopened with exponential backoff.
//  - Auth fields of the command are not checked yet.

#include <avc/ack_t.hpp>
#include <avc/turntable_command_t.hpp>
#include <chrono>
#include <memory>
#include <optional>
#include <string>

#include "core/auth/command_auth.h"
#include "core/bus/ack_book.h"
#include "core/bus/bus.h"
#include "core/bus/event_loop.h"
#include "core/bus/heartbeat.h"
#include "core/util/clock.h"
#include "drivers/turntable/lt360_device.h"
#include "drivers/turntable/turntable_controller.h"

namespace avc::turntable {

struct TurntableNodeOptions {
  std::string service = "avc-turntable";
  std::string device;  // serial device path
  int baud = 9600;
  DeviceOptions device_options;
  ControllerOptions controller;
  std::chrono::milliseconds poll_period{100};
  std::chrono::milliseconds reconnect_min{250};
  std::chrono::milliseconds reconnect_max{5000};
  // Consecutive failed polls after which the port is closed and reopened.
  int failures_before_reconnect = 3;
  // Who may turn the table: every command but STOP must be signed with the cell's key
  // (core/auth) unless unsigned commands are allowed explicitly.
  auth::VerifierOptions auth;

  std::string Validate() const;
};

class TurntableNode {
 public:
  // Subscribes and starts polling; the first connection attempt happens at once. Throws
  // std::invalid_argument for bad options.
  TurntableNode(bus::Bus& bus, bus::EventLoop& loop, bus::HeartbeatPublisher& heartbeat,
                TurntableNodeOptions options);
  ~TurntableNode();
  TurntableNode(const TurntableNode&) = delete;
  TurntableNode& operator=(const TurntableNode&) = delete;

  // Before the process ends: stops the table if a move is running (that move FAILS) and
  // publishes the final state.
  void Shutdown();

  bool connected() const { return device_ != nullptr; }

 private:
  void OnCommand(const avc::turntable_command_t& command);
  // True when the command is authentic and for this cell; else the refusal is sent and logged.
  bool Authentic(const avc::turntable_command_t& command);
  // Why the command is refused for good (malformed), or "".
  std::string Validate(const avc::turntable_command_t& command) const;
  // Why it cannot start now (no device, busy), or "": a NOT_READY answer.
  std::string NotReady(const avc::turntable_command_t& command) const;
  void Start(const avc::turntable_command_t& command);
  void Stop(const avc::turntable_command_t& command);
  void Tick();
  void TryConnect();
  void Disconnect(const std::string& why);
  void DeviceFailed(const std::exception& error);
  void FinishActive(int8_t status, const std::string& reason);
  void SendAck(const std::string& request_id, int8_t status, const std::string& reason);
  void PublishState();
  void UpdateHeartbeat();

  bus::Bus& bus_;
  bus::EventLoop& loop_;
  bus::HeartbeatPublisher& heartbeat_;
  TurntableNodeOptions options_;
  bus::AckBook acks_;
  std::optional<auth::CommandVerifier> verifier_;
  std::unique_ptr<Clock> clock_;

  std::unique_ptr<Lt360Device> device_;
  std::unique_ptr<TurntableController> controller_;
  std::string error_;  // why the device is unusable or misbehaving; "" when fine
  int consecutive_failures_ = 0;
  std::chrono::milliseconds reconnect_delay_;
  int64_t next_connect_us_ = 0;

  std::string active_request_;
  std::string active_description_;

  bus::Bus::SubscriptionId subscription_ = 0;
  bus::EventLoop::TimerId timer_ = 0;
};

}  // namespace avc::turntable
