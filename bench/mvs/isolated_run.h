#pragma once

// Runs one benchmark case in a child process, so that its peak memory is its own and a crash or
// an exhausted machine shows up as a failed case rather than a dead benchmark. The parent must
// not have started TBB's (or any other) worker threads before forking.

#include <functional>
#include <nlohmann/json.hpp>
#include <string>

namespace avc::bench {

struct IsolatedResult {
  bool ok = false;
  std::string error;          // why the case failed (exception text, signal, exit code)
  nlohmann::json result;      // what the case returned
  double peak_memory_mb = 0;  // the child's maximum resident set size
};

IsolatedResult RunIsolated(const std::function<nlohmann::json()>& run_case);

}  // namespace avc::bench
