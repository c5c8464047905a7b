#pragma once

// `avc bench calibration`: robot-world/hand-eye Monte-Carlo (closed form, Ceres, OpenCV SHAH),
// turntable axis Monte-Carlo (the paper's line intersection, closed form, Ceres), and the whole
// calibration end to end in the simulated cell, in one run.

#include <string>
#include <vector>

namespace avc::bench {

int RunCalibrationBenchmark(const std::vector<std::string>& args);

}  // namespace avc::bench
