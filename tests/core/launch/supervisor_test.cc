// The supervisor behind `avc up`, on an in-process bus with `sh -c` children: restart policies,
// backoff, exit reporting, and stopping (SIGTERM, then SIGKILL after stop_timeout).

#include "core/launch/supervisor.h"

#include <gtest/gtest.h>
#include <signal.h>

#include <avc/heartbeat_t.hpp>
#include <avc/process_info_t.hpp>
#include <avc/process_status_t.hpp>
#include <filesystem>
#include <map>

#include "core/bus/bus_options.h"
#include "core/bus/channels.h"
#include "tests/support/test_support.h"

namespace avc::launch {
namespace {

namespace fs = std::filesystem;
using avc::process_info_t;
using std::chrono::milliseconds;
using Clock = std::chrono::steady_clock;

struct Harness {
  Harness() : bus(bus::InProcessBusOptions("cell0", "test")) {
    bus.AttachTo(loop);
    bus.Subscribe<avc::process_status_t>(
        channels::kProcessStatus,
        [this](const avc::process_status_t& msg, const bus::RxInfo&) { statuses.push_back(msg); });
    bus.Subscribe<avc::heartbeat_t>(
        channels::kHeartbeat,
        [this](const avc::heartbeat_t& msg, const bus::RxInfo&) { heartbeats.push_back(msg); });
  }

  LaunchSpec Spec(std::vector<ProcessSpec> processes) const {
    LaunchSpec spec;
    spec.file = "/test/launch.toml";
    spec.log_dir = (dir.path() / "logs").string();
    spec.processes = std::move(processes);
    return spec;
  }

  static SupervisorOptions Options() {
    SupervisorOptions options;
    options.host = "testhost";
    options.backoff.initial = milliseconds(50);
    options.backoff.max = milliseconds(400);
    options.backoff.reset_after = milliseconds(10'000);
    options.status_period = milliseconds(100);
    return options;
  }

  std::string Log(const std::string& name) const {
    const fs::path path = dir.path() / "logs" / (name + ".log");
    std::error_code error;
    return fs::exists(path, error) ? testing::ReadFile(path) : "";
  }

  testing::TempDir dir{"avc-supervisor"};
  bus::Bus bus;
  bus::EventLoop loop;
  std::vector<avc::process_status_t> statuses;
  std::vector<avc::heartbeat_t> heartbeats;
};

ProcessSpec Sh(const std::string& name, const std::string& script,
               RestartPolicy restart = RestartPolicy::kOnFailure,
               milliseconds stop_timeout = milliseconds(5000)) {
  ProcessSpec spec;
  spec.name = name;
  spec.command = "/bin/sh";
  spec.args = {"-c", script};
  spec.restart = restart;
  spec.stop_timeout = stop_timeout;
  return spec;
}

process_info_t Info(const Supervisor& supervisor, const std::string& name) {
  for (const process_info_t& info : supervisor.Status().processes) {
    if (info.name == name) return info;
  }
  ADD_FAILURE() << "no process named " << name;
  return process_info_t{};
}

// Whether the shell running as name has printed "ready:<its pid>" (so its trap is set). The
// pid keeps the command line, which the log also holds, from matching.
bool Ready(const Harness& h, const Supervisor& supervisor, const std::string& name) {
  const int32_t pid = Info(supervisor, name).pid;
  return pid > 0 && h.Log(name).find("ready:" + std::to_string(pid) + "\n") != std::string::npos;
}

TEST(Supervisor, FailingProcessIsRestartedWithGrowingBackoff) {
  Harness h;
  Supervisor supervisor(h.Spec({Sh("crash", "exit 1")}), h.bus, h.loop, Harness::Options());
  supervisor.Start();
  // Every start, seen after each loop round (at most one start happens per round).
  std::vector<int64_t> starts;
  auto poll = [&] {
    const process_info_t info = Info(supervisor, "crash");
    if (info.started_utime != 0 && (starts.empty() || starts.back() != info.started_utime)) {
      starts.push_back(info.started_utime);
    }
    return info.restarts >= 4;
  };
  // The fourth restart is due 50 + 100 + 200 + 400 ms (plus run times) after the first start.
  ASSERT_TRUE(h.loop.RunUntil(poll, std::chrono::seconds(10)));
  ASSERT_EQ(starts.size(), 5u);
  const std::vector<int64_t> delays_ms = {50, 100, 200, 400};
  for (size_t i = 0; i < delays_ms.size(); ++i) {
    const int64_t gap_us = starts[i + 1] - starts[i];
    EXPECT_GE(gap_us, delays_ms[i] * 1000 - 5'000) << "restart " << i + 1;
    EXPECT_LT(gap_us, delays_ms[i] * 1000 + 1'000'000) << "restart " << i + 1;
  }
  const process_info_t info = Info(supervisor, "crash");
  EXPECT_EQ(info.restarts, 4);
  EXPECT_EQ(info.last_exit_code, 1);
  EXPECT_EQ(info.last_signal, 0);
  EXPECT_EQ(info.command, "/bin/sh -c 'exit 1'");
  EXPECT_EQ(info.log_file, (h.dir.path() / "logs" / "crash.log").string());
  EXPECT_FALSE(supervisor.finished());

  // Published on PROCESS_STATUS too, with the count climbing.
  h.bus.DispatchPending();
  ASSERT_FALSE(h.statuses.empty());
  int32_t max_restarts = -1;
  for (const avc::process_status_t& status : h.statuses) {
    EXPECT_EQ(status.host, "testhost");
    EXPECT_EQ(status.launch_file, "/test/launch.toml");
    ASSERT_EQ(status.num_processes, 1);
    EXPECT_GE(status.processes[0].restarts, max_restarts) << "restarts never go down";
    max_restarts = std::max(max_restarts, status.processes[0].restarts);
  }
  EXPECT_GE(max_restarts, 3);
  bool up_ready = false;
  for (const avc::heartbeat_t& beat : h.heartbeats) {
    up_ready |= beat.service == "avc-up" && beat.state == avc::heartbeat_t::STATE_READY;
  }
  EXPECT_TRUE(up_ready) << "avc-up heartbeat READY";

  supervisor.Stop();
  ASSERT_TRUE(h.loop.RunUntil([&] { return supervisor.finished(); }, std::chrono::seconds(5)));
  EXPECT_EQ(supervisor.exit_code(), 0) << "a stop ends with 0";
  EXPECT_EQ(Info(supervisor, "crash").state, process_info_t::STATE_EXITED);
  const std::string log = h.Log("crash");
  EXPECT_NE(log.find("starting crash (start 1)"), std::string::npos) << log;
  EXPECT_NE(log.find("starting crash (start 5)"), std::string::npos) << log;
  EXPECT_NE(log.find("exited with code 1"), std::string::npos) << log;
}

TEST(Supervisor, NeverAndCleanExitsAreNotRestarted) {
  Harness h;
  Supervisor supervisor(h.Spec({Sh("never", "exit 2", RestartPolicy::kNever),
                                Sh("clean", "exit 0", RestartPolicy::kOnFailure)}),
                        h.bus, h.loop, Harness::Options());
  supervisor.Start();
  ASSERT_TRUE(h.loop.RunUntil([&] { return supervisor.finished(); }, std::chrono::seconds(5)));
  // Longer than the first backoff delay: a restart would have happened by now.
  h.loop.RunUntil([] { return false; }, milliseconds(200));
  const process_info_t never = Info(supervisor, "never");
  EXPECT_EQ(never.state, process_info_t::STATE_FAILED);
  EXPECT_EQ(never.restarts, 0);
  EXPECT_EQ(never.last_exit_code, 2);
  EXPECT_EQ(never.pid, 0);
  const process_info_t clean = Info(supervisor, "clean");
  EXPECT_EQ(clean.state, process_info_t::STATE_EXITED);
  EXPECT_EQ(clean.restarts, 0);
  EXPECT_EQ(clean.last_exit_code, 0);
  EXPECT_EQ(supervisor.exit_code(), 1) << "one process failed";
  EXPECT_NE(h.Log("never").find("exited with code 2"), std::string::npos) << h.Log("never");
  EXPECT_EQ(h.Log("never").find("starting never (start 2)"), std::string::npos);
}

TEST(Supervisor, AllCleanExitsGiveExitCodeZeroAndAlwaysRestartsCleanExits) {
  {
    Harness h;
    Supervisor supervisor(h.Spec({Sh("a", "exit 0"), Sh("b", "exit 0", RestartPolicy::kNever)}),
                          h.bus, h.loop, Harness::Options());
    EXPECT_EQ(supervisor.Run(), 0);
    EXPECT_TRUE(supervisor.finished());
  }
  Harness h;
  Supervisor supervisor(h.Spec({Sh("again", "exit 0", RestartPolicy::kAlways)}), h.bus, h.loop,
                        Harness::Options());
  supervisor.Start();
  ASSERT_TRUE(h.loop.RunUntil([&] { return Info(supervisor, "again").restarts >= 2; },
                              std::chrono::seconds(5)));
  EXPECT_EQ(Info(supervisor, "again").last_exit_code, 0);
  supervisor.Stop();
  ASSERT_TRUE(h.loop.RunUntil([&] { return supervisor.finished(); }, std::chrono::seconds(5)));
  EXPECT_EQ(supervisor.exit_code(), 0);
}

TEST(Supervisor, StopSendsSigtermThenSigkillAfterStopTimeout) {
  Harness h;
  const std::string loop = "while :; do sleep 0.05; done";
  Supervisor supervisor(
      h.Spec({Sh("polite", "echo ready:$$; " + loop, RestartPolicy::kAlways, milliseconds(5000)),
              Sh("ignores_term", "trap '' TERM; echo ready:$$; " + loop, RestartPolicy::kAlways,
                 milliseconds(300))}),
      h.bus, h.loop, Harness::Options());
  supervisor.Start();
  // Ready means the trap is in place: a SIGTERM before it would kill the shell.
  ASSERT_TRUE(h.loop.RunUntil(
      [&] { return Ready(h, supervisor, "polite") && Ready(h, supervisor, "ignores_term"); },
      std::chrono::seconds(5)));
  const process_info_t before = Info(supervisor, "ignores_term");
  EXPECT_EQ(before.state, process_info_t::STATE_RUNNING);
  ASSERT_GT(before.pid, 0);
  const pid_t ignorer_pid = before.pid;

  const auto stop_time = Clock::now();
  supervisor.Stop();
  EXPECT_EQ(Info(supervisor, "ignores_term").state, process_info_t::STATE_STOPPING);
  std::optional<Clock::duration> polite_stopped;
  std::optional<Clock::duration> ignorer_stopped;
  ASSERT_TRUE(h.loop.RunUntil(
      [&] {
        if (!polite_stopped && Info(supervisor, "polite").pid == 0) {
          polite_stopped = Clock::now() - stop_time;
        }
        if (!ignorer_stopped && Info(supervisor, "ignores_term").pid == 0) {
          ignorer_stopped = Clock::now() - stop_time;
        }
        return supervisor.finished();
      },
      std::chrono::seconds(5)));
  ASSERT_TRUE(polite_stopped && ignorer_stopped);
  EXPECT_LT(*polite_stopped, milliseconds(1000)) << "SIGTERM stops it, long before SIGKILL";
  EXPECT_GE(*ignorer_stopped, milliseconds(290)) << "SIGKILL only after stop_timeout";
  EXPECT_LT(*ignorer_stopped, milliseconds(2300));

  const process_info_t polite = Info(supervisor, "polite");
  EXPECT_EQ(polite.state, process_info_t::STATE_EXITED);
  EXPECT_EQ(polite.last_signal, SIGTERM);
  EXPECT_EQ(polite.last_exit_code, -1);
  EXPECT_EQ(polite.restarts, 0) << "a stop is not a failure to restart";
  const process_info_t ignorer = Info(supervisor, "ignores_term");
  EXPECT_EQ(ignorer.state, process_info_t::STATE_EXITED);
  EXPECT_EQ(ignorer.last_signal, SIGKILL);
  EXPECT_EQ(ignorer.restarts, 0);
  EXPECT_EQ(supervisor.exit_code(), 0);
  errno = 0;
  EXPECT_EQ(kill(ignorer_pid, 0), -1);
  EXPECT_EQ(errno, ESRCH);
  EXPECT_NE(h.Log("polite").find("killed by SIGTERM"), std::string::npos) << h.Log("polite");
  EXPECT_NE(h.Log("ignores_term").find("killed by SIGKILL"), std::string::npos)
      << h.Log("ignores_term");

  h.bus.DispatchPending();
  ASSERT_FALSE(h.heartbeats.empty());
  EXPECT_EQ(h.heartbeats.back().service, "avc-up");
  EXPECT_EQ(h.heartbeats.back().state, avc::heartbeat_t::STATE_STOPPING);
}

TEST(Supervisor, SecondStopKillsAtOnce) {
  Harness h;
  Supervisor supervisor(
      h.Spec({Sh("ignores_term", "trap '' TERM; echo ready:$$; while :; do sleep 0.05; done",
                 RestartPolicy::kOnFailure, milliseconds(30'000))}),
      h.bus, h.loop, Harness::Options());
  supervisor.Start();
  ASSERT_TRUE(h.loop.RunUntil([&] { return Ready(h, supervisor, "ignores_term"); },
                              std::chrono::seconds(5)));
  supervisor.Stop();
  h.loop.RunUntil([] { return false; }, milliseconds(100));
  EXPECT_FALSE(supervisor.finished()) << "TERM is ignored and SIGKILL is 30 s away";
  const auto start = Clock::now();
  supervisor.Stop();
  ASSERT_TRUE(h.loop.RunUntil([&] { return supervisor.finished(); }, std::chrono::seconds(5)));
  EXPECT_LT(Clock::now() - start, milliseconds(2000));
  EXPECT_EQ(Info(supervisor, "ignores_term").last_signal, SIGKILL);
}

TEST(Supervisor, EnvironmentIsMergedAndWorkingDirUsed) {
  Harness h;
  fs::create_directories(h.dir / "work");
  ProcessSpec process = Sh("env", "echo \"env:$AVC_T_A,$AVC_T_B,$AVC_T_C:$(pwd)\"");
  process.env = {{"AVC_T_B", "proc-b"}, {"AVC_T_C", "proc-c"}};
  process.working_dir = (h.dir / "work").string();
  LaunchSpec spec = h.Spec({process});
  spec.env = {{"AVC_T_A", "file-a"}, {"AVC_T_B", "file-b"}};
  Supervisor supervisor(spec, h.bus, h.loop, Harness::Options());
  EXPECT_EQ(supervisor.Run(), 0);
  EXPECT_NE(h.Log("env").find("env:file-a,proc-b,proc-c:" + fs::canonical(h.dir / "work").string() +
                              "\n"),
            std::string::npos)
      << h.Log("env");
}

TEST(Supervisor, ProcessThatCannotStartIsReportedInItsLog) {
  Harness h;
  ProcessSpec missing;
  missing.name = "missing";
  missing.command = "/nonexistent/program";
  missing.restart = RestartPolicy::kNever;
  ProcessSpec retried = missing;
  retried.name = "retried";
  retried.restart = RestartPolicy::kOnFailure;
  Supervisor supervisor(h.Spec({missing, retried}), h.bus, h.loop, Harness::Options());
  supervisor.Start();
  ASSERT_TRUE(h.loop.RunUntil([&] { return Info(supervisor, "retried").restarts >= 2; },
                              std::chrono::seconds(5)));
  EXPECT_EQ(Info(supervisor, "missing").state, process_info_t::STATE_FAILED);
  EXPECT_EQ(Info(supervisor, "missing").restarts, 0);
  EXPECT_NE(h.Log("missing").find("/nonexistent/program"), std::string::npos) << h.Log("missing");
  EXPECT_NE(h.Log("missing").find("No such file or directory"), std::string::npos);
  supervisor.Stop();
  ASSERT_TRUE(h.loop.RunUntil([&] { return supervisor.finished(); }, std::chrono::seconds(5)));
  EXPECT_EQ(supervisor.exit_code(), 0);
}

TEST(Supervisor, UnwritableLogFolderThrowsFromStart) {
  Harness h;
  testing::WriteFile(h.dir / "file", "not a folder");
  LaunchSpec spec = h.Spec({Sh("x", "exit 0")});
  spec.log_dir = (h.dir / "file" / "logs").string();
  Supervisor supervisor(spec, h.bus, h.loop, Harness::Options());
  EXPECT_THROW(supervisor.Start(), std::runtime_error);
}

}  // namespace
}  // namespace avc::launch
