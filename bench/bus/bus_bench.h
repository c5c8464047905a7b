#pragma once

// `avc bench bus`: reliable 5 MB products between two processes over real multicast LCM, with
// the recommended bulk receive buffer and with the kernel's default one, at a steady rate and in
// a burst. Reports delivered/sent, retransmissions, latency (Send to acknowledgement) and
// throughput per configuration and phase. With --loss, the loss mode instead
// (bench/bus/bus_bench_loss.h): chunked products with received messages dropped on purpose.

#include <string>
#include <vector>

namespace avc::bench {

int RunBusBenchmark(const std::vector<std::string>& args);

}  // namespace avc::bench
