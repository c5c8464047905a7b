#pragma once

#include <string>
#include <vector>

namespace avc::bench {

// avc bench e2e: `avc demo` end to end (see e2e_bench.cc).
int RunE2eBenchmark(const std::vector<std::string>& arguments);

}  // namespace avc::bench
