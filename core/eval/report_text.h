#pragma once

// The evaluation report for people at a terminal: a plain-text summary table rendered from the
// report JSON (ToJson of the evaluation, with optional "inputs" and "coverage" members), so it
// shows exactly what the JSON holds. Distances in mm, fractions in %.

#include <nlohmann/json.hpp>
#include <string>

namespace avc::eval {

std::string FormatSummary(const nlohmann::json& report);

}  // namespace avc::eval
