#pragma once

// `avc bench merge`: model merging (paper §3.1) with injected outliers on simulated scans, the
// raw and merged clouds' distances to the ground truth side by side.

#include <string>
#include <vector>

namespace avc::bench {

int RunMergeBenchmark(const std::vector<std::string>& args);

}  // namespace avc::bench
