#pragma once

#include <string>
#include <vector>

namespace avc::bench {

// avc bench mvs: the builder's MVS against PMVS2's published run on the Middlebury
// dinoSparseRing and against the plane-sweep comparator on the same inputs, and on simulated
// plants (30 views at 1280x960) scored against the ground truth.
int RunMvsBenchmark(const std::vector<std::string>& arguments);

}  // namespace avc::bench
