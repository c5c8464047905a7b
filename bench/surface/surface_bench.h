#pragma once

// `avc bench surface`: the surfacer (paper §4, Algorithm 3) against trimmed Poisson, greedy
// projection, advancing front and Pound-style patches on points sampled on the leaves of the
// simulated plants (paper Table 4: area and accuracy).

#include <string>
#include <vector>

namespace avc::bench {

int RunSurfaceBenchmark(const std::vector<std::string>& args);

}  // namespace avc::bench
