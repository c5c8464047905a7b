#pragma once

#include <string>
#include <vector>

namespace avc::bench {

// avc bench auth: the cost of signing and checking a motion command, and a live
// `avc turntable --emulate` process under unsigned, forged, altered, misdirected, wrong-cell,
// replayed and stale commands between genuine ones: refusals per kind and whether it moved.
int RunAuthBenchmark(const std::vector<std::string>& arguments);

}  // namespace avc::bench
