#pragma once

// Table 2's "correctly clustered points": the fraction of points whose cluster is matched to their
// ground-truth label under the best one-to-one matching of clusters to labels (Hungarian).
//
// Outliers: points labelled kUnassigned in the ground truth (injected outliers) are left out of
// the numerator, the denominator and the matching, so a method is neither rewarded nor punished
// for what it does with them. Labelled points a method leaves kUnassigned count as wrong, and so do
// points of clusters left unmatched (more clusters than labels) or of labels left unmatched.

#include <cstdint>
#include <vector>

#include "core/cluster/point_set.h"

namespace avc::cluster {

// Throws std::invalid_argument when the sizes differ, an id is below kUnassigned, or no point has
// a label.
double CorrectlyClusteredFraction(const Assignment& assignment, const std::vector<int32_t>& labels);

}  // namespace avc::cluster
