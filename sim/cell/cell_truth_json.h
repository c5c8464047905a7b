#pragma once

// CellTruth as JSON, so a scan directory records the truth it was simulated with. Keys state
// their units (_m metres, _rad radians, _px pixels); rotations are row-major 3x3 matrices, so
// saving and loading reproduces every double exactly.

#include <filesystem>
#include <nlohmann/json.hpp>

#include "sim/cell/cell_truth.h"

namespace avc::sim {

nlohmann::json CellTruthToJson(const CellTruth& cell);
// Throws std::runtime_error naming the missing or malformed key, or the invalid field.
CellTruth CellTruthFromJson(const nlohmann::json& json);

// Throws std::runtime_error naming the path when the file cannot be written or read or parsed.
void SaveCellTruth(const CellTruth& cell, const std::filesystem::path& path);
CellTruth LoadCellTruth(const std::filesystem::path& path);

}  // namespace avc::sim
