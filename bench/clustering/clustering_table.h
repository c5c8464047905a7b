#pragma once

// Text rendering of a RunClusteringComparison report, laid out like the paper's Table 2.

#include <nlohmann/json.hpp>
#include <string>

namespace avc::bench {

// Rows: methods; columns: sets; cells: "accuracy % / median ms" (or skipped / error), then one
// line per spectral baseline with its speed ratio to ours per set. Throws std::invalid_argument
// when the report lacks the layout documented in clustering_comparison.h.
std::string FormatClusteringTable(const nlohmann::json& report);

}  // namespace avc::bench
