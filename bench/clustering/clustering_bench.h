#pragma once

// `avc bench clustering`: the paper's Table 2 replica — our Algorithm 2 against k-means, iPDDP,
// dense and sparse spectral clustering and PCL region growing on the six labelled sets.

#include <string>
#include <vector>

namespace avc::bench {

int RunClusteringBenchmark(const std::vector<std::string>& args);

}  // namespace avc::bench
