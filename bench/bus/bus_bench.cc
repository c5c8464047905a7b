#include "bench/bus/bus_bench.h"

#include <fmt/format.h>
#include <signal.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <avc/heartbeat_t.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>

#include "bench/bus/bus_bench_phase.h"
#include "bench/bus/bus_bench_receiver.h"
#include "bench/registry.h"
#include "core/bus/channels.h"
#include "core/bus/heartbeat.h"
#include "core/launch/child_process.h"
#include "core/launch/find_program.h"
#include "core/util/log.h"

namespace avc::bench {
namespace {

namespace fs = std::filesystem;

struct BusBenchArgs {
  double duration_s = 60;
  double rate_hz = 10;
  size_t size_bytes = 5'000'000;
  int burst = 200;
  double compare_duration_s = 10;
  int compare_burst = 20;
  int port = 7687;
  std::string cell = "bench";
  bool json = false;
  // The receiving process.
  std::string role = "sender";
  BusBenchReceiverOptions receiver;
};

// One way of configuring the bulk link, measured end to end.
struct BusConfig {
  std::string name;
  std::string description;
  std::string bulk_url;
  size_t max_message_bytes = 0;
  bool baseline = false;  // runs the shorter comparison schedule
};

struct ConfigResult {
  BusConfig config;
  std::vector<PhaseResult> phases;
  std::map<std::string, int64_t> receiver_delivered;
  int64_t receiver_duplicates = 0;
  int64_t receiver_corrupt = 0;
  std::string error;
};

std::vector<BusConfig> Configs(const BusBenchArgs& args) {
  const std::string bulk = fmt::format("udpm://239.255.76.67:{}?ttl=0", args.port + 1);
  return {
      {"recommended", "bulk recv_buf_size=4194304, products up to 8 MB in one message",
       bulk + "&recv_buf_size=4194304", bus::kDefaultMaxMessageBytes, false},
      {"default-buffer", "kernel default receive buffer, products up to 8 MB in one message", bulk,
       bus::kDefaultMaxMessageBytes, true},
      {"default-buffer-64k", "kernel default receive buffer, products chunked at 64 kB", bulk,
       64'000, true},
  };
}

std::string ControlUrl(const BusBenchArgs& args) {
  return fmt::format("udpm://239.255.76.67:{}?ttl=0", args.port);
}

bus::BusOptions SenderBusOptions(const BusBenchArgs& args, const BusConfig& config) {
  bus::BusOptions options;
  options.control_url = ControlUrl(args);
  options.bulk_url = config.bulk_url;
  options.cell = args.cell;
  options.source = "avc-bench";
  options.max_message_bytes = config.max_message_bytes;
  return options;
}

// Waits until the receiver's heartbeat says READY, so no product is sent before it listens.
bool WaitForReceiver(bus::Bus& bus, bus::EventLoop& loop, pid_t pid) {
  bool ready = false;
  const auto id = bus.Subscribe<avc::heartbeat_t>(
      channels::kHeartbeat, [&](const avc::heartbeat_t& beat, const bus::RxInfo&) {
        ready = ready || (beat.service == kBenchReceiverService && beat.pid == pid &&
                          beat.state == avc::heartbeat_t::STATE_READY);
      });
  loop.RunUntil([&] { return ready; }, std::chrono::seconds(15));
  bus.Unsubscribe(id);
  return ready;
}

void ReadReceiverReport(const fs::path& path, ConfigResult& result) {
  std::ifstream in(path);
  nlohmann::json report = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (report.is_discarded() || !report.is_object()) {
    result.error = "the receiver wrote no readable report (" + path.string() + ")";
    return;
  }
  result.receiver_delivered = report.value("delivered", std::map<std::string, int64_t>{});
  result.receiver_duplicates = report.value("duplicates", int64_t{0});
  result.receiver_corrupt = report.value("corrupt", int64_t{0});
}

// Runs the receiver as a child process (`avc bench bus --role receiver`), both phases from
// this process, then stops the receiver and reads what it counted.
ConfigResult RunConfig(const BusBenchArgs& args, const BusConfig& config, const fs::path& work) {
  ConfigResult result;
  result.config = config;
  const fs::path report = work / (config.name + ".json");
  launch::SpawnSpec spawn;
  spawn.argv = {(launch::SelfExecutableDir() / "avc").string(),
                "bench",
                "bus",
                "--role",
                "receiver",
                "--report",
                report.string(),
                "--lcm-url",
                ControlUrl(args),
                "--bulk-url",
                config.bulk_url,
                "--cell",
                args.cell};
  spawn.log_file = (work / (config.name + "-receiver.log")).string();
  launch::ChildProcess receiver = launch::ChildProcess::Spawn(spawn);

  bus::Bus bus(SenderBusOptions(args, config));
  bus::EventLoop loop;
  bus.AttachTo(loop);
  if (!WaitForReceiver(bus, loop, receiver.pid())) {
    result.error = "the receiver did not report READY within 15 s; see " + spawn.log_file;
    return result;
  }
  products::SenderOptions sender_options;
  sender_options.required_receivers = {kBenchReceiverName};
  const double duration = config.baseline ? args.compare_duration_s : args.duration_s;
  const int burst = config.baseline ? args.compare_burst : args.burst;
  const std::vector<PhaseSpec> phases = {
      {fmt::format("{}/rate", config.name), static_cast<int>(std::lround(duration * args.rate_hz)),
       args.rate_hz, args.size_bytes},
      {fmt::format("{}/burst", config.name), burst, 0, args.size_bytes},
  };
  for (const PhaseSpec& phase : phases) {
    log::Info("{}: {} products of {:.1f} MB {}", phase.name, phase.count,
              static_cast<double>(phase.payload_bytes) / 1e6,
              phase.rate_hz > 0 ? fmt::format("at {} Hz", phase.rate_hz) : "at full speed");
    result.phases.push_back(RunPhase(bus, loop, phase, sender_options));
  }
  receiver.Signal(SIGTERM);
  const std::optional<int> status = receiver.WaitFor(std::chrono::seconds(10));
  if (!status || !WIFEXITED(*status) || WEXITSTATUS(*status) != 0) {
    result.error = "the receiver did not stop cleanly (" +
                   (status ? launch::DescribeWaitStatus(*status) : std::string("still running")) +
                   "); see " + spawn.log_file;
  }
  ReadReceiverReport(report, result);
  return result;
}

int64_t ReceiverDelivered(const ConfigResult& result, const std::string& phase) {
  const auto it = result.receiver_delivered.find(phase);
  return it == result.receiver_delivered.end() ? 0 : it->second;
}

void PrintTable(const std::vector<ConfigResult>& results) {
  std::cout << fmt::format("{:<26} {:>5} {:>9} {:>5} {:>7} {:>8} {:>8} {:>8} {:>7}\n",
                           "config/phase", "sent", "delivered", "lost", "resent", "lat p50",
                           "lat p99", "lat max", "MB/s");
  for (const ConfigResult& result : results) {
    for (const PhaseResult& phase : result.phases) {
      const int64_t delivered = ReceiverDelivered(result, phase.name);
      std::cout << fmt::format(
          "{:<26} {:>5} {:>9} {:>5} {:>7} {:>6.1f}ms {:>6.1f}ms {:>6.1f}ms {:>7.0f}\n", phase.name,
          phase.sent, delivered, phase.sent - delivered, phase.chunks_retransmitted,
          phase.latency_ms.median, phase.latency_ms.p99, phase.latency_ms.max,
          phase.megabytes_per_second);
      if (!phase.first_error.empty())
        std::cout << "    first failure: " << phase.first_error << "\n";
    }
    if (!result.error.empty())
      std::cout << "  " << result.config.name << ": " << result.error << "\n";
  }
}

nlohmann::json ToJson(const BusBenchArgs& args, const std::vector<ConfigResult>& results) {
  nlohmann::json json;
  json["benchmark"] = "bus";
  json["payload_bytes"] = args.size_bytes;
  json["rate_hz"] = args.rate_hz;
  for (const ConfigResult& result : results) {
    nlohmann::json config;
    config["name"] = result.config.name;
    config["description"] = result.config.description;
    config["bulk_url"] = result.config.bulk_url;
    config["max_message_bytes"] = result.config.max_message_bytes;
    config["receiver_duplicates"] = result.receiver_duplicates;
    config["receiver_corrupt"] = result.receiver_corrupt;
    config["error"] = result.error;
    for (const PhaseResult& phase : result.phases) {
      const int64_t delivered = ReceiverDelivered(result, phase.name);
      config["phases"].push_back({{"name", phase.name},
                                  {"sent", phase.sent},
                                  {"acknowledged", phase.acknowledged},
                                  {"delivered", delivered},
                                  {"lost", phase.sent - delivered},
                                  {"failed", phase.failed},
                                  {"chunks_sent", phase.chunks_sent},
                                  {"chunks_retransmitted", phase.chunks_retransmitted},
                                  {"latency_ms_median", phase.latency_ms.median},
                                  {"latency_ms_p99", phase.latency_ms.p99},
                                  {"latency_ms_max", phase.latency_ms.max},
                                  {"seconds", phase.seconds},
                                  {"megabytes_per_second", phase.megabytes_per_second}});
    }
    json["configs"].push_back(config);
  }
  return json;
}

// Goal of the foundation issue: nothing lost with the recommended set-up, median latency under
// 50 ms at the steady rate.
bool MeetsGoal(const std::vector<ConfigResult>& results) {
  const ConfigResult& recommended = results.front();
  if (!recommended.error.empty()) return false;
  for (const PhaseResult& phase : recommended.phases) {
    if (ReceiverDelivered(recommended, phase.name) != phase.sent || phase.failed > 0) return false;
  }
  return recommended.phases.front().latency_ms.median < 50.0;
}

int RunSender(const BusBenchArgs& args) {
  const fs::path work = fs::temp_directory_path() / fmt::format("avc-bench-bus-{}", getpid());
  fs::create_directories(work);
  std::vector<ConfigResult> results;
  for (const BusConfig& config : Configs(args)) {
    log::Info("configuration {}: {}", config.name, config.description);
    results.push_back(RunConfig(args, config, work));
  }
  PrintTable(results);
  const bool goal = MeetsGoal(results);
  std::cout << fmt::format("goal (recommended: 0 lost, median latency < 50 ms at {} Hz): {}\n",
                           args.rate_hz, goal ? "met" : "NOT met");
  if (args.json) std::cout << ToJson(args, results).dump() << "\n";
  std::error_code ignored;
  fs::remove_all(work, ignored);
  return goal ? 0 : 1;
}

}  // namespace

int RunBusBenchmark(const std::vector<std::string>& arguments) {
  BusBenchArgs args;
  CLI::App app{
      "avc bench bus: 5 MB products between two processes over multicast LCM, steady rate and\n"
      "burst, with the recommended bulk receive buffer and two kernel-default baselines.",
      "avc bench bus"};
  app.add_option("--duration", args.duration_s, "seconds of the steady phase (recommended)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--rate", args.rate_hz, "products per second in the steady phase")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--size", args.size_bytes, "payload bytes per product")
      ->capture_default_str()
      ->check(CLI::Range(size_t{16}, size_t{100'000'000}));
  app.add_option("--burst", args.burst, "products sent at once in the burst phase")
      ->capture_default_str()
      ->check(CLI::Range(1, 100'000));
  app.add_option("--compare-duration", args.compare_duration_s,
                 "seconds of the steady phase for the default-buffer baselines")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--compare-burst", args.compare_burst, "burst size for the baselines")
      ->capture_default_str()
      ->check(CLI::Range(1, 100'000));
  app.add_option("--port", args.port,
                 "control UDP port; bulk uses the next (own ports, not a cell's)")
      ->capture_default_str()
      ->check(CLI::Range(1024, 65534));
  app.add_flag("--json", args.json, "print the results as one JSON line at the end");
  app.add_option("--role", args.role, "internal: 'receiver' runs the receiving process")
      ->check(CLI::IsMember({"sender", "receiver"}))
      ->group("");
  app.add_option("--report", args.receiver.report_file, "internal: receiver report file")
      ->group("");
  app.add_option("--lcm-url", args.receiver.bus.lcm_url, "internal")->group("");
  app.add_option("--bulk-url", args.receiver.bus.bulk_url, "internal")->group("");
  app.add_option("--cell", args.receiver.bus.cell, "internal")->group("");
  if (const auto exit_code = ParseBenchmarkArguments(app, arguments)) return *exit_code;
  if (args.role == "receiver") return RunBusBenchReceiver(args.receiver);
  return RunSender(args);
}

}  // namespace avc::bench
