// Phase 3's redundant-view removal on hand-made visibility: views that only repeat what others
// see go, least useful first, and no patch drops below min(1, its score with every view).

#include "services/planner/redundant_views.h"

#include <gtest/gtest.h>

namespace avc::planner {
namespace {

TEST(KeepNonRedundant, DropsRepeatsButKeepsEveryPatchAtItsScore) {
  VisibilityOptions options;
  options.min_views = 2;
  // Patches 0-2. Views 0 and 1 see everything; view 2 repeats patch 0; view 3 is the only
  // third view of patch 2 but patch 2 already passes with two.
  const std::vector<PatchesSeen> seen = {{1, 1, 1}, {1, 1, 1}, {1, 0, 0}, {0, 0, 1}};
  const std::vector<bool> keep = KeepNonRedundant(seen, options);
  EXPECT_EQ(keep, (std::vector<bool>{true, true, false, false}));
}

TEST(KeepNonRedundant, APatchBelowTheTargetKeepsEveryViewOfIt) {
  VisibilityOptions options;
  options.min_views = 3;
  // Patch 1 is seen by views 1 and 2 only (score 2/3): both must stay; view 3 repeats patch 0,
  // which has four views.
  const std::vector<PatchesSeen> seen = {{1, 0}, {1, 1}, {1, 1}, {1, 0}};
  const std::vector<bool> keep = KeepNonRedundant(seen, options);
  EXPECT_TRUE(keep[1]);
  EXPECT_TRUE(keep[2]);
  EXPECT_EQ(std::count(keep.begin(), keep.end(), false), 1);
  // Protected views stay whatever they add.
  const std::vector<bool> all = KeepNonRedundant(seen, options, {true, true, true, true});
  EXPECT_EQ(std::count(all.begin(), all.end(), false), 0);
  EXPECT_TRUE(KeepNonRedundant({}, options).empty());
}

}  // namespace
}  // namespace avc::planner
