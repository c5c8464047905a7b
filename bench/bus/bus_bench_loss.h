#pragma once

// The loss mode of `avc bench bus` (issue 11, reliability): chunked products between two
// processes while a fraction of received messages is dropped on purpose in both (chunks in the
// receiver, acknowledgements in the sender, Bus::InjectReceiveLoss with fixed seeds). Per loss
// rate: products sent, delivered exactly once, duplicates, lost, retransmissions, latency and the
// time cost against the loss-free run of the same invocation.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "bench/bus/bus_bench_run.h"

namespace avc::bench {

struct LossBenchOptions {
  std::vector<double> rates;  // loss-free reference run is added in front
  double duration_s = 20;     // steady phase per rate
  double rate_hz = 10;
  size_t size_bytes = 5'000'000;
  int burst = 50;
  // Bus cap, so each chunk is one UDP datagram (LCM sends up to 65 499 bytes as one): dropping
  // a message then costs what losing one datagram costs.
  size_t chunk_bytes = 64'000;
  uint64_t seed = 20261202;
  std::string bulk_url;
  BusLink link;
  bool json = false;
};

// Returns the exit code: 0 when every product of every rate arrived exactly once.
int RunLossBenchmark(const LossBenchOptions& options, const std::filesystem::path& work);

}  // namespace avc::bench
