#pragma once

// avc bench real: `avc reconstruct` on a real scan (by default the shared ROMI arabidopsis scan)
// as its own process, measured against the scanner's own reconstruction of the same plant:
// MVS points and mesh (precision and recall at 1, 2 and 5 mm, area, pieces), masks per view,
// height and width, and wall time and peak memory at 1/4, 1/2 and all of the views.

#include <string>
#include <vector>

namespace avc::bench {

int RunRealBenchmark(const std::vector<std::string>& args);

}  // namespace avc::bench
