#pragma once

// The leaves' figures of a reconstruction scored against a simulated plant, as `avc demo`,
// `avc bench e2e` and `avc bench surface --scans` report them: from the per-organ figures of an
// evaluation's JSON (`avc eval`'s report, eval::ToJson), areas summed, accuracy and precision
// weighted by the reconstruction's samples, recall by the truth's. The pot and soil, which the
// masks leave out on purpose, and the stem do not count.

#include <nlohmann/json.hpp>
#include <string>

namespace avc::eval {

// {"area_ratio", "accuracy_mean_mm", "precision_2mm", "recall_2mm", "fscore_2mm"}; the
// evaluation must have scored at 2 mm.
nlohmann::json LeafFigures(const nlohmann::json& evaluation);

// Those figures as one line for people, e.g. "the leaves: 95.3 % of their area, precision
// 98.9 % and recall 95.7 % at 2 mm, mean error 0.25 mm".
std::string FormatLeafFigures(const nlohmann::json& figures);

}  // namespace avc::eval
