// Phase 3's redundant-view removal on hand-made visibility: views that only repeat what others
// see go, least useful first, and every patch passing with all views still passes; a failing
// patch holds its views only when asked to.

#include "services/planner/redundant_views.h"

#include <gtest/gtest.h>

#include <stdexcept>

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

TEST(KeepNonRedundant, APatchBelowTheTargetHoldsItsViewsOnlyWhenAsked) {
  VisibilityOptions options;
  options.min_views = 3;
  // Patch 0 has four views and passes with any three. Patch 1 is seen by views 1 and 2 only
  // (score 2/3), which no choice of views makes pass.
  const std::vector<PatchesSeen> seen = {{1, 0}, {1, 1}, {1, 1}, {1, 0}};
  // The paper's rule: only patch 0 counts, so exactly one of its four views goes (the least
  // useful: each is one of four, none critical; ties go to the later capture).
  const std::vector<bool> keep = KeepNonRedundant(seen, options);
  EXPECT_EQ(keep, (std::vector<bool>{true, true, true, false}));
  // Holding failing scores: views 1 and 2 must stay, and again one view of patch 0 goes.
  const std::vector<bool> held = KeepNonRedundant(seen, options, {}, {.hold_failing_scores = true});
  EXPECT_TRUE(held[1]);
  EXPECT_TRUE(held[2]);
  EXPECT_EQ(std::count(held.begin(), held.end(), false), 1);
  // Protected views stay whatever they add.
  const std::vector<bool> all = KeepNonRedundant(seen, options, {true, true, true, true});
  EXPECT_EQ(std::count(all.begin(), all.end(), false), 0);
  EXPECT_TRUE(KeepNonRedundant({}, options).empty());
}

TEST(KeepNonRedundant, AFailingPatchDoesNotHoldViewsAPassingOneNeeds) {
  VisibilityOptions options;
  options.min_views = 2;
  // Patch 0 passes with views 0 and 1; patch 1 is seen by view 2 alone (fails); view 3 repeats
  // patch 0. Without holding, view 2 adds nothing that passes and goes, as does one of 0, 1, 3.
  const std::vector<PatchesSeen> seen = {{1, 0}, {1, 0}, {0, 1}, {1, 0}};
  const std::vector<bool> keep = KeepNonRedundant(seen, options);
  EXPECT_FALSE(keep[2]);
  EXPECT_EQ(std::count(keep.begin(), keep.end(), true), 2);
  const std::vector<bool> held = KeepNonRedundant(seen, options, {}, {.hold_failing_scores = true});
  EXPECT_TRUE(held[2]);
  EXPECT_EQ(std::count(held.begin(), held.end(), true), 3);
}

TEST(KeepNonRedundant, FacesDecideWhichViewIsLeastUseful) {
  VisibilityOptions options;
  options.min_views = 2;
  // One patch of four faces, seen (half its faces or more) by all three views, so any one view
  // may go. View 0 sees faces 0-1, view 1 all four, view 2 faces 1-3. By patches no view is
  // critical and the later capture goes (view 2): faces 2 and 3 are left with one view. By faces
  // view 0 is the last needed view of face 0 only, view 2 of faces 2 and 3: view 0 goes, and
  // faces 1-3 keep two views.
  const std::vector<PatchesSeen> seen = {{1}, {1}, {1}};
  const std::vector<PatchesSeen> faces = {{1, 1, 0, 0}, {1, 1, 1, 1}, {0, 1, 1, 1}};
  EXPECT_EQ(KeepNonRedundant(seen, options), (std::vector<bool>{true, true, false}));
  EXPECT_EQ(KeepNonRedundant(seen, options, {}, {}, faces), (std::vector<bool>{false, true, true}));
  EXPECT_THROW(KeepNonRedundant(seen, options, {}, {}, {{1}}), std::invalid_argument);
}

TEST(KeepNonRedundant, ARuleOnFacesKeepsTheirCoverage) {
  VisibilityOptions options;
  options.min_views = 2;
  // The views of the test above: with all three, the four faces are seen by 2, 3, 2 and 2 views.
  // Removing view 0 leaves face 0 with one (a quarter of the covered faces lost); removing view
  // 1 or 2 leaves faces 2 and 3 with one.
  const std::vector<PatchesSeen> seen = {{1}, {1}, {1}};
  const std::vector<PatchesSeen> faces = {{1, 1, 0, 0}, {1, 1, 1, 1}, {0, 1, 1, 1}};
  EXPECT_EQ(KeepNonRedundant(seen, options, {}, {.max_covered_faces_lost = 0.2}, faces),
            (std::vector<bool>{true, true, true}));
  EXPECT_EQ(KeepNonRedundant(seen, options, {}, {.max_covered_faces_lost = 0.25}, faces),
            (std::vector<bool>{false, true, true}));
  EXPECT_THROW(KeepNonRedundant(seen, options, {}, {.max_covered_faces_lost = 1.5}, faces),
               std::invalid_argument);
  // Without faces the limit has nothing to count: the patch rule alone decides.
  EXPECT_EQ(KeepNonRedundant(seen, options, {}, {.max_covered_faces_lost = 0}),
            (std::vector<bool>{true, true, false}));
}

}  // namespace
}  // namespace avc::planner
