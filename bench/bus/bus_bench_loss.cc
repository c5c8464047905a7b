#include "bench/bus/bus_bench_loss.h"

#include <fmt/format.h>

#include <iostream>

#include "core/util/log.h"

namespace avc::bench {
namespace {

BusConfig LossConfig(const LossBenchOptions& options, double loss) {
  BusConfig config;
  config.name = fmt::format("loss-{:g}pct", 100 * loss);
  config.description = fmt::format(
      "{:g} % of received chunks and acknowledgements dropped, products chunked at {} bytes",
      100 * loss, options.chunk_bytes);
  config.bulk_url = options.bulk_url;
  config.max_message_bytes = options.chunk_bytes;
  config.loss = loss;
  config.loss_seed = options.seed;
  config.phases = RateThenBurst(config.name, options.duration_s, options.rate_hz, options.burst,
                                options.size_bytes);
  return config;
}

bool ExactlyOnce(const ConfigResult& result) {
  if (!result.error.empty()) return false;
  for (const PhaseResult& phase : result.phases) {
    if (ReceiverDelivered(result, phase.name) != phase.sent || phase.failed > 0 ||
        ReceiverDuplicates(result, phase.name) != 0) {
      return false;
    }
  }
  return true;
}

double Ratio(double value, double reference) { return reference > 0 ? value / reference : 0; }

// Chunks a product is cut into: first transmissions over products.
double ChunksPerProduct(const PhaseResult& phase) {
  return phase.sent > 0
             ? static_cast<double>(phase.chunks_sent - phase.chunks_retransmitted) / phase.sent
             : 0;
}

void PrintLossTable(const std::vector<ConfigResult>& results) {
  const ConfigResult& reference = results.front();
  std::cout << fmt::format(
      "{:<20} {:>5} {:>9} {:>4} {:>4} {:>6} {:>7} {:>7} {:>6} {:>9} {:>9} {:>6} {:>6}\n",
      "loss/phase", "sent", "delivered", "dup", "lost", "failed", "chunks", "resent", "max tx",
      "lat p50", "lat p99", "p50 x", "time x");
  for (const ConfigResult& result : results) {
    for (size_t i = 0; i < result.phases.size(); ++i) {
      const PhaseResult& phase = result.phases[i];
      const PhaseResult* base = i < reference.phases.size() ? &reference.phases[i] : nullptr;
      const int64_t delivered = ReceiverDelivered(result, phase.name);
      std::cout << fmt::format(
          "{:<20} {:>5} {:>9} {:>4} {:>4} {:>6} {:>7} {:>7} {:>6} {:>7.1f}ms {:>7.1f}ms {:>6.2f} "
          "{:>6.2f}\n",
          phase.name, phase.sent, delivered, ReceiverDuplicates(result, phase.name),
          phase.sent - delivered, phase.failed, phase.chunks_sent, phase.chunks_retransmitted,
          phase.max_attempts, phase.latency_ms.median, phase.latency_ms.p99,
          base ? Ratio(phase.latency_ms.median, base->latency_ms.median) : 0,
          base ? Ratio(phase.seconds, base->seconds) : 0);
      if (!phase.first_error.empty())
        std::cout << "    first failure: " << phase.first_error << "\n";
    }
    std::cout << fmt::format(
        "  {}: dropped on purpose {} chunks (receiver) and {} acknowledgements (sender); {} "
        "chunks lost otherwise\n",
        result.config.name, result.chunks_dropped, result.acks_dropped,
        ChunksLostUninjected(result));
    if (!result.error.empty())
      std::cout << "  " << result.config.name << ": " << result.error << "\n";
  }
}

nlohmann::json ToJson(const LossBenchOptions& options, const std::vector<ConfigResult>& results) {
  nlohmann::json json;
  json["benchmark"] = "bus";
  json["mode"] = "loss";
  json["payload_bytes"] = options.size_bytes;
  json["rate_hz"] = options.rate_hz;
  json["chunk_bytes"] = options.chunk_bytes;
  json["seed"] = options.seed;
  if (!results.empty() && !results.front().phases.empty()) {
    json["chunks_per_product"] = ChunksPerProduct(results.front().phases.front());
  }
  const ConfigResult& reference = results.front();
  for (const ConfigResult& result : results) {
    nlohmann::json config = ToJson(result);
    config["exactly_once"] = ExactlyOnce(result);
    for (size_t i = 0; i < result.phases.size() && i < reference.phases.size(); ++i) {
      config["phases"][i]["latency_median_vs_lossless"] =
          Ratio(result.phases[i].latency_ms.median, reference.phases[i].latency_ms.median);
      config["phases"][i]["seconds_vs_lossless"] =
          Ratio(result.phases[i].seconds, reference.phases[i].seconds);
    }
    json["configs"].push_back(config);
  }
  return json;
}

}  // namespace

int RunLossBenchmark(const LossBenchOptions& options, const std::filesystem::path& work) {
  std::vector<double> rates = {0.0};
  for (double rate : options.rates) {
    if (rate > 0) rates.push_back(rate);
  }
  std::vector<ConfigResult> results;
  for (double loss : rates) {
    const BusConfig config = LossConfig(options, loss);
    log::Info("configuration {}: {}", config.name, config.description);
    results.push_back(RunConfig(options.link, config, work));
  }
  PrintLossTable(results);
  if (!results.front().phases.empty()) {
    std::cout << fmt::format("products of {} bytes in {:g} chunks of at most {} bytes\n",
                             options.size_bytes, ChunksPerProduct(results.front().phases.front()),
                             options.chunk_bytes);
  }
  bool all = true;
  for (const ConfigResult& result : results) all = all && ExactlyOnce(result);
  std::cout << fmt::format("exactly once at every loss rate: {}\n", all ? "met" : "NOT met");
  if (options.json) std::cout << ToJson(options, results).dump() << "\n";
  return all ? 0 : 1;
}

}  // namespace avc::bench
