#pragma once

// What every long-running AVC process needs, set up the one way: log name, bus from flags and
// environment, event loop, 1 Hz heartbeat, and a clean stop on SIGINT/SIGTERM (heartbeat
// STOPPING, the service's stop hook, then Run() returns 0).
//
//   bus::ServiceRuntime runtime("avc-collect", flags);
//   MyNode node(runtime.bus(), ...);
//   runtime.PublishConfig(table.ToToml(options));
//   runtime.OnStop([&] { node.Flush(); });
//   runtime.heartbeat().Set(bus::ServiceState::kReady, "waiting for products");
//   return runtime.Run();

#include <functional>
#include <memory>
#include <string>

#include "core/bus/bus.h"
#include "core/bus/bus_options.h"
#include "core/bus/config_publisher.h"
#include "core/bus/event_loop.h"
#include "core/bus/heartbeat.h"

namespace avc::bus {

class ServiceRuntime {
 public:
  // Throws std::invalid_argument (bad flags/environment) or BusError (cannot open the bus).
  ServiceRuntime(const std::string& service, const BusFlags& flags);
  ServiceRuntime(const ServiceRuntime&) = delete;
  ServiceRuntime& operator=(const ServiceRuntime&) = delete;

  Bus& bus() { return *bus_; }
  EventLoop& loop() { return loop_; }
  HeartbeatPublisher& heartbeat() { return *heartbeat_; }
  const std::string& service() const { return service_; }

  // Publishes the configuration in force on CONFIG from now on (config_publisher.h); returns its
  // SHA-256, which the service names in what it makes.
  const std::string& PublishConfig(std::string toml_text);

  // Runs on the loop thread when a termination signal arrives, before Run() returns.
  void OnStop(std::function<void()> on_stop) { on_stop_ = std::move(on_stop); }
  // Runs the event loop until SIGINT/SIGTERM or Quit; returns the exit code.
  int Run();

 private:
  std::string service_;
  EventLoop loop_;
  std::unique_ptr<Bus> bus_;
  std::unique_ptr<HeartbeatPublisher> heartbeat_;
  std::unique_ptr<ConfigPublisher> config_;
  std::function<void()> on_stop_;
};

}  // namespace avc::bus
