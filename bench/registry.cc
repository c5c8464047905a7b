#include "bench/registry.h"

#include "bench/bus/bus_bench.h"

namespace avc::bench {

const std::vector<Benchmark>& AllBenchmarks() {
  static const std::vector<Benchmark> benchmarks = {
      {"bus",
       "5 MB image products between two processes at 10 Hz and in a burst, with the "
       "recommended and the default receive buffer: delivered/sent, retransmissions, latency",
       RunBusBenchmark},
  };
  return benchmarks;
}

const Benchmark* FindBenchmark(const std::string& name) {
  for (const Benchmark& benchmark : AllBenchmarks()) {
    if (benchmark.name == name) return &benchmark;
  }
  return nullptr;
}

}  // namespace avc::bench
