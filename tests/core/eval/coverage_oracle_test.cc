// The ground-truth greedy reference: which views it takes, in which order, and what they cover.

#include "core/eval/coverage_oracle.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace avc::eval {
namespace {

TEST(CoverageOracle, TakesTheViewsThatCoverMostFirst) {
  // Five samples; view 0 sees 0-2, view 1 sees 2-3, view 2 sees 3-4.
  const std::vector<std::vector<uint8_t>> seen = {
      {1, 1, 1, 0, 0}, {0, 0, 1, 1, 0}, {0, 0, 0, 1, 1}};
  const OracleSelection one = GreedyCoverageSelection(seen, 1, 3);
  EXPECT_EQ(one.order, (std::vector<size_t>{0, 2}));  // view 1 then adds nothing
  ASSERT_EQ(one.coverage.size(), 2u);
  EXPECT_DOUBLE_EQ(one.coverage[0], 0.6);
  EXPECT_DOUBLE_EQ(one.coverage[1], 1.0);
}

TEST(CoverageOracle, CompletingSamplesWinsOverStartingNewOnes) {
  // Two views are needed. Views 0 and 3 tie first (gain 3); the lower index wins. Then view 1
  // would complete sample 2 and start 3 (gain 2 + 1), view 3 start three samples (gain 3), and
  // view 2 completes two (gain 2 + 2): it is taken.
  const std::vector<std::vector<uint8_t>> seen = {
      {1, 1, 1, 0, 0, 0}, {0, 0, 1, 1, 0, 0}, {1, 1, 0, 0, 0, 0}, {0, 0, 0, 1, 1, 1}};
  const OracleSelection two = GreedyCoverageSelection(seen, 2, 2);
  EXPECT_EQ(two.order, (std::vector<size_t>{0, 2}));
  EXPECT_DOUBLE_EQ(two.coverage[0], 0.0);
  EXPECT_DOUBLE_EQ(two.coverage[1], 2.0 / 6);
}

TEST(CoverageOracle, StopsAtTheLimitAndOnBadInput) {
  const std::vector<std::vector<uint8_t>> seen = {{1, 0}, {0, 1}};
  EXPECT_EQ(GreedyCoverageSelection(seen, 1, 1).order.size(), 1u);
  EXPECT_TRUE(GreedyCoverageSelection({}, 1, 5).order.empty());
  EXPECT_THROW(GreedyCoverageSelection(seen, 0, 2), std::invalid_argument);
  EXPECT_THROW(GreedyCoverageSelection({{1, 0}, {1}}, 1, 2), std::invalid_argument);
}

}  // namespace
}  // namespace avc::eval
