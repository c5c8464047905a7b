#include "core/launch/supervisor.h"

#include <fmt/chrono.h>
#include <fmt/format.h>
#include <signal.h>
#include <string.h>
#include <sys/wait.h>

#include <algorithm>
#include <avc/process_info_t.hpp>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <optional>
#include <stdexcept>

#include "core/bus/channels.h"
#include "core/launch/child_process.h"
#include "core/util/clock.h"
#include "core/util/host.h"
#include "core/util/log.h"

namespace avc::launch {
namespace {

using avc::process_info_t;
using std::chrono::milliseconds;

std::string SignalName(int signo) {
  const char* abbrev = sigabbrev_np(signo);
  return abbrev != nullptr ? "SIG" + std::string(abbrev) : "signal " + std::to_string(signo);
}

std::string Seconds(milliseconds duration) {
  return fmt::format("{:.1f} s", static_cast<double>(duration.count()) / 1000.0);
}

// The command line as a shell would need it, for logs and status.
std::string CommandLine(const ProcessSpec& spec) {
  std::string line = spec.command;
  for (const std::string& arg : spec.args) {
    const bool plain = !arg.empty() && arg.find_first_not_of(
                                           "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                           "0123456789_-.,/:=+@%") == std::string::npos;
    line += " ";
    if (plain) {
      line += arg;
    } else {
      line += "'";
      for (char c : arg) line += c == '\'' ? std::string("'\\''") : std::string(1, c);
      line += "'";
    }
  }
  return line;
}

// One line in a process's own log file, so the file tells its own story.
void AppendToLog(const std::string& log_file, const std::string& text) {
  std::ofstream out(log_file, std::ios::app);
  const std::time_t now = std::time(nullptr);
  out << fmt::format("===== {:%Y-%m-%d %H:%M:%S} avc up: {} =====\n", fmt::localtime(now), text);
}

}  // namespace

struct Supervisor::Process {
  ProcessSpec spec;
  std::string command_line;
  std::string log_file;
  std::optional<ChildProcess> child;
  int8_t state = process_info_t::STATE_STARTING;
  int32_t restarts = 0;
  int32_t last_exit_code = -1;
  int32_t last_signal = 0;
  bool ended_cleanly = false;
  int64_t started_utime = 0;
  int64_t started_monotonic_us = 0;
  Backoff backoff;
  bus::EventLoop::TimerId restart_timer = 0;
  bus::EventLoop::TimerId kill_timer = 0;
};

Supervisor::Supervisor(LaunchSpec spec, bus::Bus& bus, bus::EventLoop& loop,
                       SupervisorOptions options)
    : spec_(std::move(spec)), bus_(bus), loop_(loop), options_(std::move(options)) {
  if (options_.host.empty()) options_.host = HostName();
  for (const ProcessSpec& process_spec : spec_.processes) {
    auto process = std::make_unique<Process>();
    process->spec = process_spec;
    process->command_line = CommandLine(process_spec);
    process->log_file =
        (std::filesystem::path(spec_.log_dir) / (process_spec.name + ".log")).string();
    process->backoff = Backoff(options_.backoff);
    processes_.push_back(std::move(process));
  }
}

Supervisor::~Supervisor() {
  for (auto& process : processes_) {
    if (process->restart_timer) loop_.CancelTimer(process->restart_timer);
    if (process->kill_timer) loop_.CancelTimer(process->kill_timer);
  }
  if (status_timer_) loop_.CancelTimer(status_timer_);
  if (started_) {
    // The loop may outlive us: its signal callback must no longer reach this object.
    loop_.QuitOnTerminationSignals();
    signal(SIGCHLD, SIG_DFL);
  }
  // Children still running are killed by ~ChildProcess.
}

void Supervisor::Start() {
  if (started_) throw std::logic_error("Supervisor::Start called twice");
  std::error_code error;
  std::filesystem::create_directories(spec_.log_dir, error);
  if (error) {
    throw std::runtime_error("cannot create the log folder '" + spec_.log_dir +
                             "': " + error.message());
  }
  started_ = true;
  loop_.OnSignals({SIGCHLD, SIGINT, SIGTERM}, [this](int signo) { OnSignal(signo); });
  heartbeat_ = std::make_unique<bus::HeartbeatPublisher>(bus_, loop_, "avc-up");
  // Reaping here too means a lost SIGCHLD delays an exit by a period at most.
  status_timer_ = loop_.AddTimer(
      options_.status_period,
      [this] {
        Reap();
        PublishStatus();
      },
      /*repeating=*/true);
  log::Info("{}: starting {} process(es), logs in {}", spec_.file, processes_.size(),
            spec_.log_dir);
  for (auto& process : processes_) StartProcess(*process);
  UpdateHeartbeat();
  PublishStatus();
  CheckFinished();
}

void Supervisor::Stop() { BeginShutdown("stop requested"); }

int Supervisor::Run() {
  Start();
  while (!finished_ && !loop_.quitting()) loop_.RunOnce(std::chrono::seconds(1));
  if (!finished_) {
    // Someone else ended the loop: the children must not outlive the supervisor.
    log::Warn("event loop quit while processes were running: killing them");
    processes_.clear();
    return 1;
  }
  return exit_code_;
}

void Supervisor::OnSignal(int signo) {
  if (signo == SIGCHLD) {
    Reap();
  } else {
    BeginShutdown("received " + SignalName(signo));
  }
}

void Supervisor::StartProcess(Process& process) {
  SpawnSpec spawn;
  spawn.argv.push_back(process.spec.command);
  spawn.argv.insert(spawn.argv.end(), process.spec.args.begin(), process.spec.args.end());
  spawn.env = spec_.env;
  for (const auto& [key, value] : process.spec.env) spawn.env[key] = value;
  spawn.working_dir = process.spec.working_dir;
  spawn.log_file = process.log_file;
  AppendToLog(process.log_file, fmt::format("starting {} (start {}): {}", process.spec.name,
                                            process.restarts + 1, process.command_line));
  try {
    process.child = ChildProcess::Spawn(spawn);
  } catch (const std::exception& e) {
    log::Error("{}: {}", process.spec.name, e.what());
    AppendToLog(process.log_file, e.what());
    process.last_exit_code = -1;
    process.last_signal = 0;
    process.ended_cleanly = false;
    if (process.spec.restart == RestartPolicy::kNever) {
      process.state = process_info_t::STATE_FAILED;
    } else {
      ScheduleRestart(process, milliseconds(0));
    }
    return;
  }
  process.state = process_info_t::STATE_RUNNING;
  process.started_utime = SystemClock().NowMicros();
  process.started_monotonic_us = MonotonicMicros();
  log::Info("{} started (pid {}): {}", process.spec.name, process.child->pid(),
            process.command_line);
}

void Supervisor::Reap() {
  bool changed = false;
  for (auto& process : processes_) {
    if (!process->child) continue;
    if (const std::optional<int> status = process->child->TryWait()) {
      HandleExit(*process, *status);
      changed = true;
    }
  }
  if (changed) {
    UpdateHeartbeat();
    PublishStatus();
    CheckFinished();
  }
}

void Supervisor::HandleExit(Process& process, int wait_status) {
  const pid_t pid = process.child->pid();
  process.child.reset();
  if (process.kill_timer) {
    loop_.CancelTimer(process.kill_timer);
    process.kill_timer = 0;
  }
  const milliseconds uptime((MonotonicMicros() - process.started_monotonic_us) / 1000);
  process.last_exit_code = WIFEXITED(wait_status) ? WEXITSTATUS(wait_status) : -1;
  process.last_signal = WIFSIGNALED(wait_status) ? WTERMSIG(wait_status) : 0;
  process.ended_cleanly = WIFEXITED(wait_status) && WEXITSTATUS(wait_status) == 0;
  const std::string what = DescribeWaitStatus(wait_status);
  AppendToLog(process.log_file, fmt::format("{} (pid {}) {} after {}", process.spec.name, pid, what,
                                            Seconds(uptime)));
  if (stopping_) {
    log::Info("{} (pid {}) {}", process.spec.name, pid, what);
    process.state = process_info_t::STATE_EXITED;
    return;
  }
  const bool restart =
      process.spec.restart == RestartPolicy::kAlways ||
      (process.spec.restart == RestartPolicy::kOnFailure && !process.ended_cleanly);
  if (process.ended_cleanly) {
    log::Info("{} (pid {}) {} after {}", process.spec.name, pid, what, Seconds(uptime));
  } else {
    log::Warn("{} (pid {}) {} after {}; its output is in {}", process.spec.name, pid, what,
              Seconds(uptime), process.log_file);
  }
  if (restart) {
    ScheduleRestart(process, uptime);
  } else {
    process.state =
        process.ended_cleanly ? process_info_t::STATE_EXITED : process_info_t::STATE_FAILED;
    log::Info("{} will not be restarted (restart = \"{}\")", process.spec.name,
              RestartPolicyName(process.spec.restart));
  }
}

void Supervisor::ScheduleRestart(Process& process, milliseconds uptime) {
  const milliseconds delay = process.backoff.NextDelay(uptime);
  process.state = process_info_t::STATE_BACKOFF;
  log::Info("restarting {} in {} (restart {})", process.spec.name, Seconds(delay),
            process.restarts + 1);
  process.restart_timer = loop_.AddTimer(delay, [this, &process] {
    process.restart_timer = 0;
    ++process.restarts;
    StartProcess(process);
    UpdateHeartbeat();
    PublishStatus();
    CheckFinished();
  });
}

void Supervisor::BeginShutdown(const std::string& reason) {
  if (finished_) return;
  if (stopping_) {
    log::Warn("{} while stopping: killing every process now", reason);
    for (auto& process : processes_) {
      if (process->child) process->child->Signal(SIGKILL);
    }
    return;
  }
  stopping_ = true;
  log::Info("{}: stopping every process", reason);
  if (heartbeat_) heartbeat_->Set(bus::ServiceState::kStopping, reason);
  for (auto& owned : processes_) {
    Process& process = *owned;
    if (process.restart_timer) {
      loop_.CancelTimer(process.restart_timer);
      process.restart_timer = 0;
    }
    if (!process.child) {
      if (process.state == process_info_t::STATE_BACKOFF ||
          process.state == process_info_t::STATE_STARTING) {
        process.state = process_info_t::STATE_EXITED;
      }
      continue;
    }
    process.state = process_info_t::STATE_STOPPING;
    log::Info("stopping {} (pid {}): SIGTERM, SIGKILL after {}", process.spec.name,
              process.child->pid(), Seconds(process.spec.stop_timeout));
    process.child->Signal(SIGTERM);
    process.kill_timer = loop_.AddTimer(process.spec.stop_timeout, [&process] {
      process.kill_timer = 0;
      if (!process.child) return;
      log::Warn("{} (pid {}) did not stop within {}: SIGKILL", process.spec.name,
                process.child->pid(), Seconds(process.spec.stop_timeout));
      process.child->Signal(SIGKILL);
    });
  }
  PublishStatus();
  Reap();
  CheckFinished();
}

void Supervisor::CheckFinished() {
  if (finished_ || !started_) return;
  const bool all_ended = std::all_of(processes_.begin(), processes_.end(), [](const auto& p) {
    return !p->child && p->restart_timer == 0;
  });
  if (!all_ended) return;
  finished_ = true;
  const bool all_clean = std::all_of(processes_.begin(), processes_.end(),
                                     [](const auto& p) { return p->ended_cleanly; });
  exit_code_ = (stopping_ || all_clean) ? 0 : 1;
  if (stopping_) {
    log::Info("every process has stopped");
  } else {
    log::Info("every process has ended and none will restart: {}",
              all_clean ? "all exited with code 0" : "some failed");
  }
  if (status_timer_) {
    loop_.CancelTimer(status_timer_);
    status_timer_ = 0;
  }
  if (heartbeat_) heartbeat_->Set(bus::ServiceState::kStopping, "every process has ended");
  PublishStatus();
}

avc::process_status_t Supervisor::Status() const {
  avc::process_status_t status;
  status.host = options_.host;
  status.launch_file = spec_.file;
  for (const auto& process : processes_) {
    process_info_t info;
    info.name = process->spec.name;
    info.command = process->command_line;
    info.pid = process->child ? static_cast<int32_t>(process->child->pid()) : 0;
    info.state = process->state;
    info.restarts = process->restarts;
    info.last_exit_code = process->last_exit_code;
    info.last_signal = process->last_signal;
    info.started_utime = process->started_utime;
    info.log_file = process->log_file;
    status.processes.push_back(std::move(info));
  }
  status.num_processes = static_cast<int32_t>(status.processes.size());
  return status;
}

void Supervisor::PublishStatus() {
  avc::process_status_t status = Status();
  try {
    bus_.Publish(channels::kProcessStatus, status);
  } catch (const bus::BusError& e) {
    log::Warn("process status not sent: {}", e.what());
  }
}

void Supervisor::UpdateHeartbeat() {
  if (!heartbeat_ || stopping_ || finished_) return;
  const auto running = std::count_if(processes_.begin(), processes_.end(),
                                     [](const auto& p) { return p->child.has_value(); });
  const auto failed = std::count_if(processes_.begin(), processes_.end(), [](const auto& p) {
    return p->state == process_info_t::STATE_FAILED;
  });
  std::string detail = fmt::format("{} of {} running", running, processes_.size());
  if (failed > 0) detail += fmt::format(", {} failed", failed);
  heartbeat_->Set(bus::ServiceState::kReady, detail);
}

}  // namespace avc::launch
