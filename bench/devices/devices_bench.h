#pragma once

// `avc bench devices`: time per captured view in the simulated cell — move the arm, turn the
// table, capture, transfer — broken down by step, with every driver a separate process on the
// real protocols and LCM, at real time and on a faster clock, in one run.

#include <string>
#include <vector>

namespace avc::bench {

int RunDevicesBenchmark(const std::vector<std::string>& args);

}  // namespace avc::bench
