#include "bench/registry.h"

#include "bench/bus/bus_bench.h"
#include "bench/render/render_bench.h"

namespace avc::bench {

const std::vector<Benchmark>& AllBenchmarks() {
  static const std::vector<Benchmark> benchmarks = {
      {"bus",
       "5 MB image products between two processes at 10 Hz and in a burst, with the "
       "recommended and the default receive buffer: delivered/sent, retransmissions, latency",
       RunBusBenchmark},
      {"render",
       "CPU renderer of the simulated cell: 1280x960 frame time on views around each plant "
       "preset and a 100k-triangle plant, 1/2x2/3x3 samples, 1 vs 2 threads, 1x/4x/16x pixels, "
       "peak memory",
       RunRenderBenchmark},
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
