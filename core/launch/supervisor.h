#pragma once

// Runs the processes of a launch file on an EventLoop (procman semantics):
// starts them with output in <log_dir>/<name>.log, reaps them on SIGCHLD, restarts them per
// policy with a growing backoff, publishes process_status_t on PROCESS_STATUS at 1 Hz and on
// every change plus its own "avc-up" heartbeat, and on SIGTERM/SIGINT stops them all (SIGTERM,
// then SIGKILL after stop_timeout).

#include <avc/process_status_t.hpp>
#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "core/bus/bus.h"
#include "core/bus/event_loop.h"
#include "core/bus/heartbeat.h"
#include "core/launch/backoff.h"
#include "core/launch/launch_file.h"

namespace avc::launch {

struct SupervisorOptions {
  std::string host;  // reported in process_status_t; empty = this machine's name
  BackoffPolicy backoff;
  std::chrono::milliseconds status_period{1000};
};

class Supervisor {
 public:
  // spec is already filtered to this host with its commands resolved (ForHost,
  // ResolveCommands). bus and loop must outlive the supervisor.
  Supervisor(LaunchSpec spec, bus::Bus& bus, bus::EventLoop& loop, SupervisorOptions options = {});
  ~Supervisor();
  Supervisor(const Supervisor&) = delete;
  Supervisor& operator=(const Supervisor&) = delete;

  // Creates the log folder, routes SIGCHLD, SIGINT and SIGTERM on loop to the supervisor (the
  // loop must not use OnSignals for anything else), and starts every process. Throws
  // std::runtime_error when the log folder cannot be created.
  void Start();
  // Stops every process as on SIGTERM; a second call kills those still running at once.
  void Stop();
  // Start(), then runs the loop until finished(); returns exit_code().
  int Run();

  // True once no process runs and none will restart.
  bool finished() const { return finished_; }
  // 0 after a stop, or when every process ended with exit code 0; 1 otherwise.
  int exit_code() const { return exit_code_; }
  // The report published on PROCESS_STATUS.
  avc::process_status_t Status() const;

 private:
  struct Process;

  void OnSignal(int signo);
  void StartProcess(Process& process);
  void Reap();
  void HandleExit(Process& process, int wait_status);
  void ScheduleRestart(Process& process, std::chrono::milliseconds uptime);
  void BeginShutdown(const std::string& reason);
  void CheckFinished();
  void PublishStatus();
  void UpdateHeartbeat();

  LaunchSpec spec_;
  bus::Bus& bus_;
  bus::EventLoop& loop_;
  SupervisorOptions options_;
  std::vector<std::unique_ptr<Process>> processes_;
  std::unique_ptr<bus::HeartbeatPublisher> heartbeat_;
  bus::EventLoop::TimerId status_timer_ = 0;
  bool started_ = false;
  bool stopping_ = false;
  bool finished_ = false;
  int exit_code_ = 0;
};

}  // namespace avc::launch
