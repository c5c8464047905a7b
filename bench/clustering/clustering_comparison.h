#pragma once

// Runs the paper's method and every baseline on each point set (paper Table 2) and reports
// accuracy, median time and the speed ratio of the spectral baselines to ours as JSON:
//
// {"benchmark": "clustering", "repeats": R, "dense_spectral_max_points": N,
//  "sets": [{"name", "points", "clusters", "labelled"}],
//  "methods": [{"name", "results": [{"set", "status": "ok" | "skipped" | "error",
//               "reason" (skipped/error only), "accuracy" (number or null), "median_ms",
//               "runs_ms": [...], "clusters_found", "unassigned", "repeatable"}]}],
//  "speed_ratios": [{"set", "dense_spectral_over_ours", "sparse_spectral_over_ours"}]}
//
// "results" are in the order of "sets"; a ratio is null when either side did not run.

#include <nlohmann/json.hpp>
#include <vector>

#include "bench/clustering/comparison_options.h"

namespace avc::bench {

// Throws std::invalid_argument when repeats < 1 or K cannot be found (clusters = 0 and a set
// without labels). A method that throws on a set is reported with status "error" and its message.
nlohmann::json RunClusteringComparison(const std::vector<cluster::PointSet>& sets,
                                       const ComparisonOptions& options);

}  // namespace avc::bench
