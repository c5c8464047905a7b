#include "services/planner/redundant_views.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace avc::planner {
namespace {

// Patches this view keeps at the threshold: seen by it and by exactly min_views views in all.
size_t CriticalPatches(const PatchesSeen& seen, const PatchViewCounts& counts, int min_views) {
  size_t critical = 0;
  for (size_t p = 0; p < seen.size(); ++p) critical += seen[p] && counts[p] == min_views;
  return critical;
}

bool ScoresHold(const PatchViewCounts& counts, const std::vector<double>& floor,
                const VisibilityOptions& options) {
  const std::vector<double> scores = PatchScores(counts, options);
  for (size_t p = 0; p < scores.size(); ++p) {
    if (scores[p] < floor[p] - 1e-12) return false;
  }
  return true;
}

size_t CoveredCount(const PatchViewCounts& counts, int min_views) {
  return static_cast<size_t>(
      std::count_if(counts.begin(), counts.end(), [&](int c) { return c >= min_views; }));
}

}  // namespace

std::vector<bool> KeepNonRedundant(const std::vector<PatchesSeen>& seen,
                                   const VisibilityOptions& options,
                                   const std::vector<bool>& protected_views, const PruneRule& rule,
                                   const std::vector<PatchesSeen>& faces_seen) {
  std::vector<bool> keep(seen.size(), true);
  if (seen.empty()) return keep;
  if (!faces_seen.empty() && faces_seen.size() != seen.size()) {
    throw std::invalid_argument(
        fmt::format("redundant views: faces seen by {} views, patches seen by {}",
                    faces_seen.size(), seen.size()));
  }
  if (!(rule.max_covered_faces_lost >= 0 && rule.max_covered_faces_lost <= 1)) {
    throw std::invalid_argument(
        fmt::format("redundant views: max_covered_faces_lost {} is not a fraction in [0, 1]",
                    rule.max_covered_faces_lost));
  }
  // Usefulness is counted on the faces when given, else on the patches.
  const std::vector<PatchesSeen>& useful = faces_seen.empty() ? seen : faces_seen;
  PatchViewCounts useful_counts;
  for (const PatchesSeen& view : useful) AddView(view, &useful_counts);
  PatchViewCounts counts;
  for (const PatchesSeen& view : seen) AddView(view, &counts);
  std::vector<double> floor = PatchScores(counts, options);
  for (double& score : floor) score = score >= 1.0 ? 1.0 : (rule.hold_failing_scores ? score : 0.0);
  // The fewest faces that must stay covered (only when usefulness is counted on faces).
  const size_t covered_floor =
      faces_seen.empty()
          ? 0
          : static_cast<size_t>(
                std::ceil((1.0 - rule.max_covered_faces_lost) *
                          static_cast<double>(CoveredCount(useful_counts, options.min_views))));

  std::vector<bool> tried(seen.size(), false);
  while (true) {
    // The least useful view not yet tried.
    size_t best = seen.size();
    size_t best_critical = std::numeric_limits<size_t>::max();
    for (size_t v = seen.size(); v-- > 0;) {
      if (!keep[v] || tried[v] || (v < protected_views.size() && protected_views[v])) continue;
      const size_t critical = CriticalPatches(useful[v], useful_counts, options.min_views);
      if (critical < best_critical) {
        best = v;
        best_critical = critical;
      }
    }
    if (best == seen.size()) break;
    tried[best] = true;
    RemoveView(seen[best], &counts);
    RemoveView(useful[best], &useful_counts);
    // A view that cannot go now never can: later removals only lower the counts.
    if (ScoresHold(counts, floor, options) &&
        CoveredCount(useful_counts, options.min_views) >= covered_floor) {
      keep[best] = false;
    } else {
      AddView(seen[best], &counts);
      AddView(useful[best], &useful_counts);
    }
  }
  return keep;
}

}  // namespace avc::planner
