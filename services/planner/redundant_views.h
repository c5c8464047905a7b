#pragma once

// Phase 3 of Algorithm 1 (line 24): images that can go without lowering the evaluation. A view
// may be removed when, without it, every patch that passes with all views still passes (the
// paper's rule). A patch that fails with all views (the proxy's hidden or phantom surface,
// seen by fewer than min_views of any views) does not hold its views back unless
// `hold_failing_scores`, which keeps each such patch at its score with all views. Views are
// tried least useful first: fewest patches for which the view is one of exactly min_views views
// (the patches it keeps at the threshold), ties by later capture; usefulness is recomputed after
// each removal. Given `faces_seen` (per view, FacesSeenBy), usefulness is counted on the patches'
// sampled faces instead: a view goes first when it is the last needed view of the fewest faces,
// which a patch that passes with half its faces seen does not tell; the rule can then also limit
// how many of the faces covered with all images lose their coverage.

#include <cstdint>
#include <vector>

#include "services/planner/patch_visibility.h"

namespace avc::planner {

struct PruneRule {
  bool hold_failing_scores = false;
  // With `faces_seen`: at most this fraction of the faces seen by min_views views with all
  // images may drop below min_views (1: no limit, the paper's rule). The patch rule alone cannot
  // tell which view is a face's third when a patch passes with half its faces seen.
  double max_covered_faces_lost = 1.0;
};

// Per view: true to keep. `protected_views` (e.g. Phase 1's) are never removed when given.
// Throws std::invalid_argument for faces_seen of another length than seen, or a fraction
// outside [0, 1].
std::vector<bool> KeepNonRedundant(const std::vector<PatchesSeen>& seen,
                                   const VisibilityOptions& options,
                                   const std::vector<bool>& protected_views = {},
                                   const PruneRule& rule = {},
                                   const std::vector<PatchesSeen>& faces_seen = {});

}  // namespace avc::planner
