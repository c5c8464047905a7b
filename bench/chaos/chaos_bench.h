#pragma once

// `avc bench chaos`: scans that survive a SIGKILL of any of their processes at a random moment,
// and several cells scanning at once on one network, each compared byte for byte with an
// undisturbed scan (see chaos_bench.cc).

#include <string>
#include <vector>

namespace avc::bench {

int RunChaosBenchmark(const std::vector<std::string>& arguments);

}  // namespace avc::bench
