#pragma once

// The evaluation report as JSON: every metric with its thresholds, sample counts and seeds. The
// text summary and the HTML page are rendered from this document, so all three agree.

#include <nlohmann/json.hpp>

#include "core/eval/coverage.h"
#include "core/eval/metrics.h"

namespace avc::eval {

// Distances in metres, areas in m^2. Per-point data (distances, view counts) is left out.
nlohmann::json ToJson(const EvalResult& result);
nlohmann::json ToJson(const CoverageResult& result);

}  // namespace avc::eval
