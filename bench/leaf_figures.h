#pragma once

// The leaves' figures of a reconstruction scored against a simulated plant, as `avc bench e2e`
// and `avc bench surface --scans` report them: from the per-organ figures of an evaluation's
// JSON (`avc eval`'s report, eval::ToJson), areas summed, accuracy and precision weighted by
// the reconstruction's samples, recall by the truth's.

#include <nlohmann/json.hpp>

namespace avc::bench {

// {"area_ratio", "accuracy_mean_mm", "precision_2mm", "recall_2mm", "fscore_2mm"}; the
// evaluation must have scored at 2 mm.
nlohmann::json LeafFigures(const nlohmann::json& evaluation);

}  // namespace avc::bench
