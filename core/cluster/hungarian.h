#pragma once

// Optimal one-to-one assignment (Hungarian / Kuhn-Munkres, O(n^3) with potentials).

#include <vector>

namespace avc::cluster {

// cost: rows x cols, rectangular allowed (every row of the smaller side is matched). Returns, per
// row, its column or -1 when rows > cols and the row is left out. Minimises the summed cost.
// Throws std::invalid_argument for ragged rows or non-finite costs.
std::vector<int> SolveAssignment(const std::vector<std::vector<double>>& cost);

}  // namespace avc::cluster
