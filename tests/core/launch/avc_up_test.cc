// `avc up` as a real process over real udpm LCM (inside tests/support/in_netns): it starts
// `avc record` and `avc collect`, restarts the collector after a SIGKILL, reports the restart on
// PROCESS_STATUS, and on SIGTERM stops everything and exits 0.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>

#include <avc/heartbeat_t.hpp>
#include <avc/process_info_t.hpp>
#include <avc/process_status_t.hpp>
#include <cerrno>
#include <filesystem>
#include <map>
#include <set>

#include "core/bus/bus.h"
#include "core/bus/bus_options.h"
#include "core/bus/channels.h"
#include "core/bus/event_loop.h"
#include "core/launch/child_process.h"
#include "tests/support/test_support.h"

namespace avc::launch {
namespace {

namespace fs = std::filesystem;
using avc::heartbeat_t;
using avc::process_info_t;
using std::chrono::seconds;

constexpr char kCell[] = "launchup";

// Kills, by pid, whatever the test saw running if it ends early; the processes are not our
// children (avc up is), so they cannot be reaped here.
struct PidGuard {
  ~PidGuard() {
    for (pid_t pid : pids) {
      if (pid > 0) kill(pid, SIGKILL);
    }
  }
  std::set<pid_t> pids;
};

bool Gone(pid_t pid) {
  errno = 0;
  return kill(pid, 0) == -1 && errno == ESRCH;
}

TEST(AvcUp, RestartsAKilledServiceAndStopsEverythingOnSigterm) {
  testing::TempDir dir("avc-up");
  const std::string avc = testing::Executable("avc").string();
  ASSERT_TRUE(fs::exists(avc)) << avc;
  const fs::path launch_file = dir / "cell.toml";
  testing::WriteFile(launch_file, R"(log_dir = "logs"

[env]
AVC_CELL = ")" + std::string(kCell) + R"("

[[process]]
name = "recorder"
command = ")" + avc + R"("
args = ["record", "-o", "run.lcmlog"]
working_dir = "logs"
restart = "never"

[[process]]
name = "collector"
command = ")" + avc + R"("
args = ["collect", "-o", "products"]
working_dir = "logs"
restart = "on-failure"
stop_timeout = 3
)");

  bus::BusFlags flags;
  flags.cell = kCell;
  bus::Bus bus(bus::ResolveBusOptions(flags, "avc-up-test"));
  bus::EventLoop loop;
  bus.AttachTo(loop);
  std::map<std::string, heartbeat_t> latest;  // by service
  std::map<std::string, std::set<int32_t>> ready_pids;
  bus.Subscribe<heartbeat_t>(channels::kHeartbeat,
                             [&](const heartbeat_t& beat, const bus::RxInfo&) {
                               latest[beat.service] = beat;
                               if (beat.state == heartbeat_t::STATE_READY)
                                 ready_pids[beat.service].insert(beat.pid);
                             });
  std::optional<avc::process_status_t> status;
  bus.Subscribe<avc::process_status_t>(
      channels::kProcessStatus,
      [&](const avc::process_status_t& msg, const bus::RxInfo&) { status = msg; });
  auto info = [&](const std::string& name) -> std::optional<process_info_t> {
    if (!status) return std::nullopt;
    for (const process_info_t& process : status->processes) {
      if (process.name == name) return process;
    }
    return std::nullopt;
  };

  SpawnSpec spec;
  spec.argv = {avc, "up", launch_file.string()};
  spec.log_file = (dir / "up.log").string();
  ChildProcess up = ChildProcess::Spawn(spec);
  PidGuard guard;
  auto up_log = [&] { return "avc up output:\n" + testing::ReadFile(dir / "up.log"); };

  // Both services up and READY, as they say themselves.
  auto ready_pid = [&](const std::string& service) -> int32_t {
    auto it = latest.find(service);
    return it != latest.end() && it->second.state == heartbeat_t::STATE_READY ? it->second.pid : 0;
  };
  ASSERT_TRUE(loop.RunUntil(
      [&] { return ready_pid("avc-record") > 0 && ready_pid("avc-collect") > 0; }, seconds(15)))
      << up_log();
  const pid_t recorder_pid = ready_pid("avc-record");
  const pid_t first_collector_pid = ready_pid("avc-collect");
  guard.pids = {recorder_pid, first_collector_pid};
  ASSERT_NE(recorder_pid, up.pid());
  ASSERT_TRUE(loop.RunUntil(
      [&] {
        auto collector = info("collector");
        return collector && collector->pid == first_collector_pid;
      },
      seconds(5)))
      << "PROCESS_STATUS names the collector's pid";
  EXPECT_EQ(info("collector")->restarts, 0);
  EXPECT_EQ(info("recorder")->pid, recorder_pid);
  EXPECT_EQ(latest.count("avc-up"), 1u) << "avc up has its own heartbeat";

  // Killed hard, the collector comes back as a new process and says READY again.
  ASSERT_EQ(kill(first_collector_pid, SIGKILL), 0);
  ASSERT_TRUE(loop.RunUntil(
      [&] {
        const int32_t pid = ready_pid("avc-collect");
        return pid > 0 && pid != first_collector_pid;
      },
      seconds(10)))
      << up_log();
  const pid_t second_collector_pid = ready_pid("avc-collect");
  guard.pids.insert(second_collector_pid);
  EXPECT_TRUE(Gone(first_collector_pid)) << "the killed collector was reaped by avc up";
  ASSERT_TRUE(loop.RunUntil(
      [&] {
        auto collector = info("collector");
        return collector && collector->pid == second_collector_pid;
      },
      seconds(5)))
      << up_log();
  const process_info_t collector = *info("collector");
  EXPECT_EQ(collector.restarts, 1);
  EXPECT_EQ(collector.state, process_info_t::STATE_RUNNING);
  EXPECT_EQ(collector.last_signal, SIGKILL);
  EXPECT_EQ(collector.last_exit_code, -1);
  const process_info_t recorder = *info("recorder");
  EXPECT_EQ(recorder.restarts, 0);
  EXPECT_EQ(recorder.pid, recorder_pid);
  EXPECT_EQ(recorder.state, process_info_t::STATE_RUNNING);
  EXPECT_EQ(ready_pids["avc-record"], std::set<int32_t>{recorder_pid});

  // SIGTERM: everything stops and avc up exits 0.
  ASSERT_TRUE(up.Signal(SIGTERM));
  const std::optional<int> up_status = up.WaitFor(seconds(10));
  ASSERT_TRUE(up_status.has_value()) << "avc up did not exit within 10 s\n" << up_log();
  EXPECT_EQ(DescribeWaitStatus(*up_status), "exited with code 0") << up_log();
  EXPECT_TRUE(Gone(recorder_pid)) << recorder_pid;
  EXPECT_TRUE(Gone(second_collector_pid)) << second_collector_pid;
  if (Gone(recorder_pid) && Gone(second_collector_pid)) guard.pids.clear();

  const fs::path logs = dir / "logs";
  ASSERT_TRUE(fs::is_regular_file(logs / "run.lcmlog"));
  EXPECT_GT(fs::file_size(logs / "run.lcmlog"), 0u);
  ASSERT_TRUE(fs::is_regular_file(logs / "recorder.log"));
  ASSERT_TRUE(fs::is_regular_file(logs / "collector.log"));
  EXPECT_TRUE(fs::is_directory(logs / "products"));
  const std::string collector_log = testing::ReadFile(logs / "collector.log");
  EXPECT_NE(collector_log.find("killed by SIGKILL"), std::string::npos) << collector_log;
  EXPECT_NE(collector_log.find("(start 2)"), std::string::npos) << collector_log;
  const std::string recorder_log = testing::ReadFile(logs / "recorder.log");
  EXPECT_NE(recorder_log.find("exited with code 0"), std::string::npos) << recorder_log;
}

// Runs `avc up` with args to its end (bounded); returns its wait status and its output.
std::pair<std::string, std::string> RunUp(const testing::TempDir& dir,
                                          const std::vector<std::string>& args) {
  SpawnSpec spec;
  spec.argv = {testing::Executable("avc").string(), "up"};
  spec.argv.insert(spec.argv.end(), args.begin(), args.end());
  spec.log_file = (dir / "out.txt").string();
  fs::remove(spec.log_file);
  ChildProcess up = ChildProcess::Spawn(spec);
  const std::optional<int> status = up.WaitFor(seconds(10));
  return {status ? DescribeWaitStatus(*status) : "still running",
          testing::ReadFile(dir / "out.txt")};
}

TEST(AvcUp, BadLaunchFileExitsWithCode2NamingFileAndLine) {
  testing::TempDir dir("avc-up");
  const std::string file = (dir / "bad.yaml").string();
  testing::WriteFile(file, "process:\n  - name: p\n    comand: sh\n");
  const auto [status, output] = RunUp(dir, {file});
  EXPECT_EQ(status, "exited with code 2") << output;
  EXPECT_NE(output.find(file + ":3: unknown key 'comand'"), std::string::npos) << output;
  EXPECT_FALSE(fs::exists(dir / "logs")) << "nothing starts from a bad file";

  const std::string missing = (dir / "cmd.toml").string();
  testing::WriteFile(missing, "[[process]]\nname = \"p\"\n\ncommand = \"avc-no-such-cmd\"\n");
  const auto [status2, output2] = RunUp(dir, {missing});
  EXPECT_EQ(status2, "exited with code 2") << output2;
  EXPECT_NE(output2.find(missing + ":4: command 'avc-no-such-cmd'"), std::string::npos) << output2;

  const std::string elsewhere = (dir / "elsewhere.toml").string();
  testing::WriteFile(elsewhere,
                     "[[process]]\nname = \"p\"\ncommand = \"sh\"\nhost = \"some-other-host\"\n");
  const auto [status3, output3] = RunUp(dir, {elsewhere, "--host", "this-host"});
  EXPECT_EQ(status3, "exited with code 2") << output3;
  EXPECT_NE(output3.find("none of its 1 processes runs on host 'this-host'"), std::string::npos)
      << output3;
}

}  // namespace
}  // namespace avc::launch
