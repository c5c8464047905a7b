#pragma once

// One configuration of `avc bench bus`, end to end: starts the receiving process, runs the
// configuration's phases from this process, stops the receiver and reads what it counted.
// Shared by the buffer comparison and the loss mode.

#include <cstdint>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bench/bus/bus_bench_phase.h"

namespace avc::bench {

// Where both processes meet: the control URL and the cell (the bulk URL is per configuration).
struct BusLink {
  std::string control_url;
  std::string cell;
};

// One way of configuring the bulk link, measured end to end.
struct BusConfig {
  std::string name;
  std::string description;
  std::string bulk_url;
  size_t max_message_bytes = 0;  // the bus cap, and so the chunk size
  // Fraction of received messages dropped on purpose (Bus::InjectReceiveLoss): product chunks in
  // the receiver, acknowledgements in the sender, each process with its own fixed seed.
  double loss = 0;
  uint64_t loss_seed = 0;
  std::vector<PhaseSpec> phases;
};

struct ConfigResult {
  BusConfig config;
  std::vector<PhaseResult> phases;
  // Per phase: products the receiver handed to its consumer, and those it handed over again.
  std::map<std::string, int64_t> receiver_delivered;
  std::map<std::string, int64_t> receiver_duplicate_deliveries;
  int64_t receiver_chunks = 0;            // chunks that reached the product receiver
  int64_t receiver_duplicate_chunks = 0;  // chunks of products already delivered
  int64_t receiver_corrupt = 0;
  int64_t chunks_dropped = 0;  // injected, in the receiver
  int64_t acks_dropped = 0;    // injected, in the sender
  std::string error;
};

// The two phases every configuration runs: duration_s at rate_hz, then a burst of burst products.
std::vector<PhaseSpec> RateThenBurst(const std::string& config_name, double duration_s,
                                     double rate_hz, int burst, size_t payload_bytes);

ConfigResult RunConfig(const BusLink& link, const BusConfig& config,
                       const std::filesystem::path& work);

int64_t ReceiverDelivered(const ConfigResult& result, const std::string& phase);
int64_t ReceiverDuplicates(const ConfigResult& result, const std::string& phase);
// Chunks the sender published that reached neither the receiver nor the injected loss: what the
// network and the socket buffers lost on their own.
int64_t ChunksLostUninjected(const ConfigResult& result);

// Everything measured about one configuration, for --json.
nlohmann::json ToJson(const ConfigResult& result);

}  // namespace avc::bench
