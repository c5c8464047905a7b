#pragma once

// The benchmarks `avc bench NAME` can run.

#include <CLI/CLI.hpp>
#include <filesystem>
#include <functional>
#include <optional>
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

// Parses a benchmark's arguments (those after NAME) into app. Returns nullopt to go on, or the
// exit code when parsing ended the run (--help, or a bad argument already reported).
std::optional<int> ParseBenchmarkArguments(CLI::App& app, const std::vector<std::string>& args);

// The shared real data (../shared/data/README.md): $AVC_SHARED_DATA, else ../shared/data from
// the working directory (the repository's root).
std::filesystem::path SharedDataDir();
const Benchmark* FindBenchmark(const std::string& name);

}  // namespace avc::bench
