#pragma once

// A heartbeat published from a thread of its own, for a process whose main loop blocks for
// seconds at a time (the scan plans views and reconstructs in its own thread). Other processes
// then tell "busy" from "gone": the beats stop only when the process dies or loses the network,
// which is what the robot driver's watchdog must notice. Says STOPPING when destroyed.

#include <string>
#include <thread>

#include "core/bus/bus.h"
#include "core/bus/event_loop.h"
#include "core/bus/heartbeat.h"

namespace avc::bus {

class BackgroundHeartbeat {
 public:
  BackgroundHeartbeat(Bus& bus, std::string service, EventLoop::Duration period);
  ~BackgroundHeartbeat();
  BackgroundHeartbeat(const BackgroundHeartbeat&) = delete;
  BackgroundHeartbeat& operator=(const BackgroundHeartbeat&) = delete;

  // From any thread; published at once.
  void Set(ServiceState state, std::string detail = "");

 private:
  EventLoop loop_;  // the thread's own; Bus::Publish is safe from any thread
  HeartbeatPublisher publisher_;
  std::thread thread_;
};

}  // namespace avc::bus
