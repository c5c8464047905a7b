#pragma once

// Phase 3 of Algorithm 1 (line 24): images that can go without lowering the evaluation. A view
// may be removed when, without it, every patch still scores at least min(1, its score with all
// views). Views are tried least useful first: fewest patches for which the view is one of exactly
// min_views views (the patches it keeps at the threshold), ties by later capture; usefulness is
// recomputed after each removal.

#include <cstdint>
#include <vector>

#include "services/planner/patch_visibility.h"

namespace avc::planner {

// Per view: true to keep. `protected_views` (e.g. Phase 1's) are never removed when given.
std::vector<bool> KeepNonRedundant(const std::vector<PatchesSeen>& seen,
                                   const VisibilityOptions& options,
                                   const std::vector<bool>& protected_views = {});

}  // namespace avc::planner
