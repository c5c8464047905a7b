#include "bench/bus/bus_bench_run.h"

#include <fmt/format.h>
#include <signal.h>

#include <avc/heartbeat_t.hpp>
#include <cmath>
#include <fstream>
#include <optional>

#include "bench/bus/bus_bench_receiver.h"
#include "core/bus/channels.h"
#include "core/launch/child_process.h"
#include "core/launch/find_program.h"
#include "core/util/log.h"

namespace avc::bench {
namespace {

namespace fs = std::filesystem;

bus::BusOptions SenderBusOptions(const BusLink& link, const BusConfig& config) {
  bus::BusOptions options;
  options.control_url = link.control_url;
  options.bulk_url = config.bulk_url;
  options.cell = link.cell;
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
  result.receiver_duplicate_deliveries =
      report.value("duplicate_deliveries", std::map<std::string, int64_t>{});
  result.receiver_chunks = report.value("chunks", int64_t{0});
  result.receiver_duplicate_chunks = report.value("duplicates", int64_t{0});
  result.receiver_corrupt = report.value("corrupt", int64_t{0});
  result.chunks_dropped = report.value("injected_drops", int64_t{0});
}

launch::SpawnSpec ReceiverSpawn(const BusLink& link, const BusConfig& config,
                                const fs::path& report, const fs::path& log) {
  launch::SpawnSpec spawn;
  spawn.argv = {(launch::SelfExecutableDir() / "avc").string(),
                "bench",
                "bus",
                "--role",
                "receiver",
                "--report",
                report.string(),
                "--lcm-url",
                link.control_url,
                "--bulk-url",
                config.bulk_url,
                "--cell",
                link.cell};
  if (config.loss > 0) {
    spawn.argv.insert(spawn.argv.end(), {"--receive-loss", fmt::format("{}", config.loss),
                                         "--loss-seed", std::to_string(config.loss_seed)});
  }
  spawn.log_file = log.string();
  return spawn;
}

int64_t CountOf(const std::map<std::string, int64_t>& counts, const std::string& phase) {
  const auto it = counts.find(phase);
  return it == counts.end() ? 0 : it->second;
}

}  // namespace

std::vector<PhaseSpec> RateThenBurst(const std::string& config_name, double duration_s,
                                     double rate_hz, int burst, size_t payload_bytes) {
  return {
      {config_name + "/rate", static_cast<int>(std::lround(duration_s * rate_hz)), rate_hz,
       payload_bytes},
      {config_name + "/burst", burst, 0, payload_bytes},
  };
}

ConfigResult RunConfig(const BusLink& link, const BusConfig& config, const fs::path& work) {
  ConfigResult result;
  result.config = config;
  const fs::path report = work / (config.name + ".json");
  const launch::SpawnSpec spawn =
      ReceiverSpawn(link, config, report, work / (config.name + "-receiver.log"));
  launch::ChildProcess receiver = launch::ChildProcess::Spawn(spawn);

  bus::Bus bus(SenderBusOptions(link, config));
  bus::EventLoop loop;
  bus.AttachTo(loop);
  if (!WaitForReceiver(bus, loop, receiver.pid())) {
    result.error = "the receiver did not report READY within 15 s; see " + spawn.log_file;
    return result;
  }
  if (config.loss > 0) {
    // A different seed from the receiver's, so the two directions lose independently.
    bus.InjectReceiveLoss(bus.FullChannel(channels::kProductAck), config.loss,
                          config.loss_seed + 1);
  }
  products::SenderOptions sender_options;
  sender_options.required_receivers = {kBenchReceiverName};
  for (const PhaseSpec& phase : config.phases) {
    log::Info("{}: {} products of {:.1f} MB {}", phase.name, phase.count,
              static_cast<double>(phase.payload_bytes) / 1e6,
              phase.rate_hz > 0 ? fmt::format("at {} Hz", phase.rate_hz) : "at full speed");
    result.phases.push_back(RunPhase(bus, loop, phase, sender_options));
  }
  result.acks_dropped = bus.stats().injected_drops;
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
  return CountOf(result.receiver_delivered, phase);
}

int64_t ReceiverDuplicates(const ConfigResult& result, const std::string& phase) {
  return CountOf(result.receiver_duplicate_deliveries, phase);
}

int64_t ChunksLostUninjected(const ConfigResult& result) {
  int64_t sent = 0;
  for (const PhaseResult& phase : result.phases) sent += phase.chunks_sent;
  return sent - result.receiver_chunks - result.chunks_dropped;
}

nlohmann::json ToJson(const ConfigResult& result) {
  nlohmann::json config;
  config["name"] = result.config.name;
  config["description"] = result.config.description;
  config["bulk_url"] = result.config.bulk_url;
  config["max_message_bytes"] = result.config.max_message_bytes;
  config["loss"] = result.config.loss;
  config["receiver_chunks"] = result.receiver_chunks;
  config["receiver_duplicates"] = result.receiver_duplicate_chunks;
  config["receiver_corrupt"] = result.receiver_corrupt;
  config["chunks_dropped"] = result.chunks_dropped;
  config["acks_dropped"] = result.acks_dropped;
  config["chunks_lost_uninjected"] = ChunksLostUninjected(result);
  config["error"] = result.error;
  for (const PhaseResult& phase : result.phases) {
    const int64_t delivered = ReceiverDelivered(result, phase.name);
    config["phases"].push_back({{"name", phase.name},
                                {"sent", phase.sent},
                                {"acknowledged", phase.acknowledged},
                                {"delivered", delivered},
                                {"lost", phase.sent - delivered},
                                {"duplicate_deliveries", ReceiverDuplicates(result, phase.name)},
                                {"failed", phase.failed},
                                {"max_attempts", phase.max_attempts},
                                {"chunks_sent", phase.chunks_sent},
                                {"chunks_retransmitted", phase.chunks_retransmitted},
                                {"latency_ms_median", phase.latency_ms.median},
                                {"latency_ms_p99", phase.latency_ms.p99},
                                {"latency_ms_max", phase.latency_ms.max},
                                {"seconds", phase.seconds},
                                {"megabytes_per_second", phase.megabytes_per_second}});
  }
  return config;
}

}  // namespace avc::bench
