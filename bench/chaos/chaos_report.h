#pragma once

// What `avc bench chaos` prints: a table per group of scans, the summary, and the JSON document.

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "bench/chaos/chaos_compare.h"

namespace avc::bench {

// One scan of the benchmark and how it compared with the reference.
struct ChaosRow {
  std::string name;  // "reference", "trial 3", "cell-b"
  ChaosScanResult result;
  ChaosComparison comparison;
};

void PrintChaosTable(std::ostream& out, const std::string& title,
                     const std::vector<ChaosRow>& rows);

// Trials passed, faults survived by victim, images lost and duplicated, identical meshes, wall
// times, the concurrent cells. True when every row passed.
bool PrintChaosSummary(std::ostream& out, const ChaosRow& reference,
                       const std::vector<ChaosRow>& trials, const std::vector<ChaosRow>& cells,
                       double cells_wall_s);

nlohmann::json ChaosRowJson(const ChaosRow& row);

}  // namespace avc::bench
