#pragma once

// The receiving process of `avc bench bus`: a product receiver named "bench-receiver" on
// PRODUCT/BENCH that counts what it delivers per phase (and any product delivered twice) and, on
// SIGTERM, writes a JSON report. Optionally drops a fraction of the chunks it receives.

#include <string>

#include "core/bus/bus_options.h"

namespace avc::bench {

inline constexpr char kBenchReceiverName[] = "bench-receiver";
inline constexpr char kBenchReceiverService[] = "avc-bench-receiver";

struct BusBenchReceiverOptions {
  bus::BusFlags bus;
  std::string report_file;
  double loss = 0;  // fraction of received product chunks dropped (Bus::InjectReceiveLoss)
  uint64_t loss_seed = 0;
};

// Runs until SIGTERM/SIGINT; returns the process exit code.
int RunBusBenchReceiver(const BusBenchReceiverOptions& options);

}  // namespace avc::bench
