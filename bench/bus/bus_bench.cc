#include "bench/bus/bus_bench.h"

#include <fmt/format.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>

#include "bench/bus/bus_bench_loss.h"
#include "bench/bus/bus_bench_receiver.h"
#include "bench/bus/bus_bench_run.h"
#include "bench/registry.h"
#include "core/bus/bus_options.h"
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
  // Given --loss: the loss mode instead of the buffer comparison.
  LossBenchOptions loss;
  // The receiving process.
  std::string role = "sender";
  BusBenchReceiverOptions receiver;
};

std::string BulkUrl(const BusBenchArgs& args) {
  return fmt::format("udpm://239.255.76.67:{}?ttl=0", args.port + 1);
}
// The recommended bulk link (README "The bus").
std::string RecommendedBulkUrl(const BusBenchArgs& args) {
  return BulkUrl(args) + "&recv_buf_size=4194304";
}

BusLink Link(const BusBenchArgs& args) {
  return {fmt::format("udpm://239.255.76.67:{}?ttl=0", args.port), args.cell};
}

BusConfig BufferConfig(const BusBenchArgs& args, std::string name, std::string description,
                       std::string bulk_url, size_t max_message_bytes, bool baseline) {
  BusConfig config;
  config.name = std::move(name);
  config.description = std::move(description);
  config.bulk_url = std::move(bulk_url);
  config.max_message_bytes = max_message_bytes;
  // The baselines run the shorter comparison schedule.
  config.phases = baseline ? RateThenBurst(config.name, args.compare_duration_s, args.rate_hz,
                                           args.compare_burst, args.size_bytes)
                           : RateThenBurst(config.name, args.duration_s, args.rate_hz, args.burst,
                                           args.size_bytes);
  return config;
}

std::vector<BusConfig> Configs(const BusBenchArgs& args) {
  return {
      BufferConfig(args, "recommended",
                   "bulk recv_buf_size=4194304, products up to 8 MB in one message",
                   RecommendedBulkUrl(args), bus::kDefaultMaxMessageBytes, false),
      BufferConfig(args, "default-buffer",
                   "kernel default receive buffer, products up to 8 MB in one message",
                   BulkUrl(args), bus::kDefaultMaxMessageBytes, true),
      BufferConfig(args, "default-buffer-64k",
                   "kernel default receive buffer, products chunked at 64 kB", BulkUrl(args),
                   64'000, true),
  };
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
  for (const ConfigResult& result : results) json["configs"].push_back(ToJson(result));
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

int RunBufferComparison(const BusBenchArgs& args, const fs::path& work) {
  std::vector<ConfigResult> results;
  for (const BusConfig& config : Configs(args)) {
    log::Info("configuration {}: {}", config.name, config.description);
    results.push_back(RunConfig(Link(args), config, work));
  }
  PrintTable(results);
  const bool goal = MeetsGoal(results);
  std::cout << fmt::format("goal (recommended: 0 lost, median latency < 50 ms at {} Hz): {}\n",
                           args.rate_hz, goal ? "met" : "NOT met");
  if (args.json) std::cout << ToJson(args, results).dump() << "\n";
  return goal ? 0 : 1;
}

int RunSender(BusBenchArgs args) {
  const fs::path work = fs::temp_directory_path() / fmt::format("avc-bench-bus-{}", getpid());
  fs::create_directories(work);
  int exit_code = 0;
  if (args.loss.rates.empty()) {
    exit_code = RunBufferComparison(args, work);
  } else {
    args.loss.rate_hz = args.rate_hz;
    args.loss.size_bytes = args.size_bytes;
    args.loss.bulk_url = RecommendedBulkUrl(args);
    args.loss.link = Link(args);
    args.loss.json = args.json;
    exit_code = RunLossBenchmark(args.loss, work);
  }
  std::error_code ignored;
  fs::remove_all(work, ignored);
  return exit_code;
}

}  // namespace

int RunBusBenchmark(const std::vector<std::string>& arguments) {
  BusBenchArgs args;
  CLI::App app{
      "avc bench bus: 5 MB products between two processes over multicast LCM, steady rate and\n"
      "burst, with the recommended bulk receive buffer and two kernel-default baselines; with\n"
      "--loss, chunked products under injected message loss instead.",
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
  app.add_option("--loss", args.loss.rates,
                 "loss mode: fractions of received chunks and acknowledgements to drop in both "
                 "processes, each against a loss-free run (--loss alone: 0.01,0.05,0.2)")
      ->delimiter(',')
      ->expected(0, CLI::detail::expected_max_vector_size)
      ->default_str("0.01,0.05,0.2")
      ->check(CLI::Range(0.0, 0.9));
  app.add_option("--loss-duration", args.loss.duration_s,
                 "loss mode: seconds of the steady phase per loss rate")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--loss-burst", args.loss.burst, "loss mode: burst size per loss rate")
      ->capture_default_str()
      ->check(CLI::Range(1, 100'000));
  app.add_option("--chunk", args.loss.chunk_bytes,
                 "loss mode: bus cap, so chunk size (64000: one chunk per UDP datagram)")
      ->capture_default_str()
      ->check(CLI::Range(size_t{4'096}, bus::kDefaultMaxMessageBytes));
  app.add_option("--seed", args.loss.seed, "loss mode: seed of the injected loss")
      ->capture_default_str();
  app.add_flag("--json", args.json, "print the results as one JSON line at the end");
  app.add_option("--role", args.role, "internal: 'receiver' runs the receiving process")
      ->check(CLI::IsMember({"sender", "receiver"}))
      ->group("");
  app.add_option("--report", args.receiver.report_file, "internal: receiver report file")
      ->group("");
  app.add_option("--lcm-url", args.receiver.bus.lcm_url, "internal")->group("");
  app.add_option("--bulk-url", args.receiver.bus.bulk_url, "internal")->group("");
  app.add_option("--cell", args.receiver.bus.cell, "internal")->group("");
  app.add_option("--receive-loss", args.receiver.loss, "internal")->group("");
  app.add_option("--loss-seed", args.receiver.loss_seed, "internal")->group("");
  if (const auto exit_code = ParseBenchmarkArguments(app, arguments)) return *exit_code;
  if (args.role == "receiver") return RunBusBenchReceiver(args.receiver);
  return RunSender(args);
}

}  // namespace avc::bench
