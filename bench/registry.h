#pragma once

// The benchmarks `avc bench NAME` can run.

#include <functional>
#include <string>
#include <vector>

namespace avc::bench {

struct Benchmark {
  std::string name;
  std::string description;
  // Runs with the arguments after NAME; returns the process exit code. Prints a human-readable
  // report, and with --json one JSON document as the last line.
  std::function<int(const std::vector<std::string>& args)> run;
};

const std::vector<Benchmark>& AllBenchmarks();
const Benchmark* FindBenchmark(const std::string& name);

}  // namespace avc::bench
