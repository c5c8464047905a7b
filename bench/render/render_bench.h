#pragma once

// `avc bench render`: frame time of the simulated cell's CPU renderer on 1280x960 views around
// each plant preset and a 100k-triangle plant, against its baselines in the same run (1, 2 and 3
// samples per pixel axis; 1 thread vs 2; 1x, 4x and 16x the pixels), with peak memory.

#include <string>
#include <vector>

namespace avc::bench {

int RunRenderBenchmark(const std::vector<std::string>& args);

}  // namespace avc::bench
