// The avc commands that talk to a live bus, as real processes in a private network namespace:
// status sees a running service, spy starts lcm-spy with every AVC type, bench bus delivers
// every product; and the help they print.

#include <gtest/gtest.h>
#include <signal.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "core/launch/child_process.h"
#include "core/util/clock.h"
#include "tests/support/test_support.h"

namespace avc {
namespace {

using testing::Executable;
using testing::ReadFile;
using testing::TempDir;

struct Outcome {
  int status = -1;
  std::string output;
};

// Runs a command to completion (killed after timeout) and returns its output.
Outcome RunCommand(const std::vector<std::string>& argv, const std::filesystem::path& log,
                   std::chrono::seconds timeout) {
  launch::ChildProcess child = launch::ChildProcess::Spawn({argv, {}, "", log.string()});
  std::optional<int> status = child.WaitFor(timeout);
  if (!status) {
    child.Signal(SIGKILL);
    status = child.WaitFor(std::chrono::seconds(5));
  }
  return {status.value_or(-1), ReadFile(log)};
}

// The last non-empty line of a command's output: where --json puts its document.
std::string LastLine(const std::string& output) {
  const size_t end = output.find_last_not_of("\n");
  if (end == std::string::npos) return {};
  const size_t begin = output.rfind('\n', end);
  return output.substr(begin == std::string::npos ? 0 : begin + 1, end + 1 - (begin + 1));
}

int ExitCode(int status) { return WIFEXITED(status) ? WEXITSTATUS(status) : -1; }

TEST(CliCommands, StatusListsARunningService) {
  TempDir dir;
  launch::ChildProcess collector = launch::ChildProcess::Spawn(
      {{Executable("avc").string(), "collect", "-o", (dir / "products").string()},
       {},
       "",
       (dir / "collect.log").string()});
  nlohmann::json collect;
  std::string last_output;
  const int64_t deadline = MonotonicMicros() + 20'000'000;
  while (collect.is_null() && MonotonicMicros() < deadline) {
    std::filesystem::remove(dir / "status.log");
    const Outcome status =
        RunCommand({Executable("avc").string(), "status", "--json", "--listen", "1.2"},
                   dir / "status.log", std::chrono::seconds(10));
    last_output = status.output;
    const nlohmann::json report = nlohmann::json::parse(LastLine(status.output), nullptr, false);
    if (!report.is_object()) continue;
    for (const auto& service : report["services"]) {
      if (service["service"] == "avc-collect" && service["state"] == "READY") collect = service;
    }
  }
  ASSERT_FALSE(collect.is_null()) << "avc status never listed avc-collect as READY:\n"
                                  << last_output << "\navc collect:\n"
                                  << ReadFile(dir / "collect.log");
  EXPECT_EQ(collect["pid"].get<int>(), collector.pid());
  EXPECT_EQ(collect["cell"], "cell0");
  EXPECT_LT(collect["age_s"].get<double>(), 2.5);
  collector.Signal(SIGTERM);
  const std::optional<int> stopped = collector.WaitFor(std::chrono::seconds(10));
  ASSERT_TRUE(stopped.has_value());
  EXPECT_EQ(ExitCode(*stopped), 0) << launch::DescribeWaitStatus(*stopped);
}

TEST(CliCommands, StatusSaysWhenNobodyIsThere) {
  TempDir dir;
  const Outcome status =
      RunCommand({Executable("avc").string(), "status", "--listen", "0.3", "--cell", "empty"},
                 dir / "status.log", std::chrono::seconds(10));
  EXPECT_EQ(ExitCode(status.status), 1);
  EXPECT_NE(status.output.find("no heartbeats on cell empty"), std::string::npos) << status.output;
}

// The help a user meets first: every command listed on one line by its summary, `avc bench
// --help` with one usage line and the benchmarks it can run, and a mistyped command named.
TEST(CliCommands, HelpListsCommandsAndBenchmarks) {
  TempDir dir;
  const Outcome root = RunCommand({Executable("avc").string(), "--help"}, dir / "root.log",
                                  std::chrono::seconds(10));
  EXPECT_EQ(ExitCode(root.status), 0);
  EXPECT_NE(root.output.find("  reconstruct                 Reconstruct a plant from images with "
                             "known cameras\n"),
            std::string::npos)
      << root.output;
  const Outcome bench = RunCommand({Executable("avc").string(), "bench", "--help"},
                                   dir / "bench.log", std::chrono::seconds(10));
  EXPECT_EQ(ExitCode(bench.status), 0);
  const size_t usage = bench.output.find("Usage: avc bench [--list] NAME [BENCHMARK OPTIONS]\n");
  EXPECT_NE(usage, std::string::npos) << bench.output;
  EXPECT_EQ(bench.output.find("Usage:", usage + 1), std::string::npos) << bench.output;
  EXPECT_NE(bench.output.find("\n  clustering "), std::string::npos) << bench.output;
  const Outcome nameless = RunCommand({Executable("avc").string(), "bench"}, dir / "nameless.log",
                                      std::chrono::seconds(10));
  EXPECT_EQ(ExitCode(nameless.status), 2);
  EXPECT_NE(nameless.output.find("name a benchmark"), std::string::npos) << nameless.output;
  const Outcome typo = RunCommand({Executable("avc").string(), "recontsruct"}, dir / "typo.log",
                                  std::chrono::seconds(10));
  EXPECT_NE(ExitCode(typo.status), 0);
  EXPECT_NE(typo.output.find("avc: no command named 'recontsruct'\nRun 'avc --help'"),
            std::string::npos)
      << typo.output;
}

// avc scan takes its options from --config (TOML or YAML), --set and its flags, and refuses a bad
// one by name and origin before it touches the bus or the scan directory.
TEST(CliCommands, ScanRefusesABadOptionByNameBeforeStarting) {
  TempDir dir;
  const std::filesystem::path calibration = dir / "calibration.yaml";
  std::ofstream(calibration) << "not read: the options are checked first\n";
  const std::filesystem::path scan_dir = dir / "scan";
  const std::string avc = Executable("avc").string();
  const Outcome set = RunCommand({avc, "scan", scan_dir.string(), "--calibration",
                                  calibration.string(), "--set", "planner.max_views=0"},
                                 dir / "set.log", std::chrono::seconds(10));
  EXPECT_EQ(ExitCode(set.status), 1);
  EXPECT_NE(set.output.find("avc scan: scan: --set planner.max_views=0: 0 is below the minimum 1"),
            std::string::npos)
      << set.output;
  const std::filesystem::path yaml = dir / "scan.yaml";
  std::ofstream(yaml) << "capture:\n  encoding: gif\n";
  const Outcome file = RunCommand({avc, "scan", scan_dir.string(), "--calibration",
                                   calibration.string(), "--config", yaml.string()},
                                  dir / "file.log", std::chrono::seconds(10));
  EXPECT_EQ(ExitCode(file.status), 1);
  EXPECT_NE(file.output.find(yaml.string() + ":2 capture.encoding=gif: not png or jpeg"),
            std::string::npos)
      << file.output;
  const Outcome flag =
      RunCommand({avc, "scan", scan_dir.string(), "--calibration", calibration.string(),
                  "--keep-out", "0", "0", "0.2", "0.5", "0.1"},
                 dir / "flag.log", std::chrono::seconds(10));
  EXPECT_EQ(ExitCode(flag.status), 1);
  EXPECT_NE(flag.output.find("avc scan: scan: the safety envelope is not usable: keep_out"),
            std::string::npos)
      << flag.output;
  EXPECT_FALSE(std::filesystem::exists(scan_dir)) << "nothing is written for a refused option";
  const Outcome help =
      RunCommand({avc, "scan", "--help"}, dir / "help.log", std::chrono::seconds(10));
  EXPECT_EQ(ExitCode(help.status), 0);
  EXPECT_NE(help.output.find("  planner.max_views = none  [views, 1..10000]"), std::string::npos)
      << help.output;
}

// lcm-spy under Xvfb finds every AVC type: the jar is on its CLASSPATH and Java 17 accepts the
// Debian wrapper's options.
TEST(CliCommands, SpyStartsWithEveryMessageType) {
  if (!std::filesystem::exists("/usr/bin/xvfb-run") ||
      !std::filesystem::exists(testing::BuildDir() / "avc-lcmtypes.jar")) {
    GTEST_SKIP() << "needs xvfb-run and a JDK (both installed by scripts/setup)";
  }
  size_t types = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(testing::SourceDir() / "lcmtypes" / "avc")) {
    types += entry.path().extension() == ".lcm";
  }
  TempDir dir;
  launch::ChildProcess spy = launch::ChildProcess::Spawn(
      {{"xvfb-run", "-a", Executable("avc").string(), "spy"}, {}, "", (dir / "spy.log").string()});
  const std::string expected = "Found " + std::to_string(types) + " LCM types";
  std::string log;
  const int64_t deadline = MonotonicMicros() + 40'000'000;
  while (log.find(expected) == std::string::npos && spy.running() && MonotonicMicros() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));  // polling a log, not readiness
    log = ReadFile(dir / "spy.log");
  }
  EXPECT_NE(log.find(expected), std::string::npos) << log;
  EXPECT_EQ(log.find("Unrecognized option"), std::string::npos) << log;
  EXPECT_TRUE(spy.running()) << "lcm-spy exited early:\n" << log;
  spy.Signal(SIGTERM);
  spy.WaitFor(std::chrono::seconds(10));
}

// A small run of the bus benchmark: two real processes, every product delivered exactly once in
// every configuration, and the JSON report is complete. Products stay below the kernel default
// receive buffer (CI cannot raise rmem_max), so even the baselines must deliver everything.
TEST(CliCommands, BenchBusDeliversEveryProduct) {
  TempDir dir;
  const Outcome bench = RunCommand(
      {Executable("avc").string(), "bench", "bus", "--duration", "1", "--rate", "10", "--size",
       "100000", "--burst", "8", "--compare-duration", "0.5", "--compare-burst", "3", "--json"},
      dir / "bench.log", std::chrono::seconds(100));
  ASSERT_EQ(ExitCode(bench.status), 0) << bench.output;
  const nlohmann::json report = nlohmann::json::parse(LastLine(bench.output), nullptr, false);
  ASSERT_TRUE(report.is_object()) << bench.output;
  ASSERT_EQ(report["configs"].size(), 3u);
  for (const auto& config : report["configs"]) {
    EXPECT_EQ(config["error"], "") << config["name"];
    EXPECT_EQ(config["receiver_corrupt"], 0) << config["name"];
    ASSERT_EQ(config["phases"].size(), 2u);
    for (const auto& phase : config["phases"]) {
      EXPECT_GT(phase["sent"].get<int>(), 0) << phase["name"];
      EXPECT_EQ(phase["delivered"], phase["sent"]) << phase["name"];
      EXPECT_EQ(phase["acknowledged"], phase["sent"]) << phase["name"];
      EXPECT_EQ(phase["lost"], 0) << phase["name"];
      EXPECT_GT(phase["latency_ms_median"].get<double>(), 0) << phase["name"];
    }
  }
}

}  // namespace
}  // namespace avc
