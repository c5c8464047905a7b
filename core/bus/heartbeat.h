#pragma once

// The 1 Hz heartbeat every AVC process publishes (and again at once on every state change), so
// supervisors, the orchestrator and `avc status` know who is alive and ready.

#include <avc/heartbeat_t.hpp>
#include <string>

#include "core/bus/bus.h"
#include "core/bus/event_loop.h"

namespace avc::bus {

enum class ServiceState : int8_t {
  kStarting = avc::heartbeat_t::STATE_STARTING,
  kReady = avc::heartbeat_t::STATE_READY,
  kBusy = avc::heartbeat_t::STATE_BUSY,
  kError = avc::heartbeat_t::STATE_ERROR,
  kStopping = avc::heartbeat_t::STATE_STOPPING,
};

const char* ServiceStateName(int8_t state);

class HeartbeatPublisher {
 public:
  // Starts publishing on loop at period (1 s by default) in state STARTING.
  HeartbeatPublisher(Bus& bus, EventLoop& loop, std::string service,
                     EventLoop::Duration period = std::chrono::seconds(1));
  ~HeartbeatPublisher();
  HeartbeatPublisher(const HeartbeatPublisher&) = delete;
  HeartbeatPublisher& operator=(const HeartbeatPublisher&) = delete;

  // Publishes at once when state or detail change. Loop thread only.
  void Set(ServiceState state, std::string detail = "");
  ServiceState state() const { return state_; }
  void PublishNow();

 private:
  Bus& bus_;
  EventLoop& loop_;
  std::string service_;
  std::string host_;
  ServiceState state_ = ServiceState::kStarting;
  std::string detail_;
  int64_t started_us_;
  EventLoop::TimerId timer_;
};

}  // namespace avc::bus
