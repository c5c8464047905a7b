#pragma once

// `avc bench nbv`: the planner's active vision (Algorithm 1) against the static-camera, orbit
// and random view sets on the simulated plants, scored by ground-truth coverage.

#include <string>
#include <vector>

namespace avc::bench {

int RunNbvBenchmark(const std::vector<std::string>& args);

}  // namespace avc::bench
