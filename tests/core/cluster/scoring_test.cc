#include "core/cluster/scoring.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "core/cluster/hungarian.h"

namespace avc::cluster {
namespace {

TEST(Hungarian, SolvesAKnownMatrix) {
  // Optimum 0->1, 1->0, 2->2: 1 + 2 + 2 = 5 (greedy row minima would take 0->1, 1->1...).
  const std::vector<std::vector<double>> cost = {{4, 1, 3}, {2, 0, 5}, {3, 2, 2}};
  EXPECT_EQ(SolveAssignment(cost), (std::vector<int>{1, 0, 2}));
}

TEST(Hungarian, HandlesRectangularMatrices) {
  const std::vector<std::vector<double>> wide = {{9, 2, 7, 8}, {6, 4, 3, 7}};
  EXPECT_EQ(SolveAssignment(wide), (std::vector<int>{1, 2}));
  const std::vector<std::vector<double>> tall = {{9, 6}, {2, 4}, {7, 3}, {8, 7}};
  EXPECT_EQ(SolveAssignment(tall), (std::vector<int>{-1, 0, 1, -1}));
}

TEST(Hungarian, RejectsRaggedAndNonFinite) {
  EXPECT_THROW(SolveAssignment({{1, 2}, {3}}), std::invalid_argument);
  EXPECT_THROW(SolveAssignment({{1, std::numeric_limits<double>::infinity()}}),
               std::invalid_argument);
}

TEST(CorrectlyClusteredFraction, PermutedIdsScoreOne) {
  const std::vector<int32_t> labels = {100, 100, 101, 101, 3, 3, 3};
  const Assignment assignment = {2, 2, 0, 0, 1, 1, 1};
  EXPECT_DOUBLE_EQ(CorrectlyClusteredFraction(assignment, labels), 1.0);
}

TEST(CorrectlyClusteredFraction, CountsMismatchesUnderTheBestMatching) {
  const std::vector<int32_t> labels = {0, 0, 0, 0, 1, 1, 1, 1};
  // One label-0 point in cluster 1: 7 of 8.
  EXPECT_DOUBLE_EQ(CorrectlyClusteredFraction({5, 5, 5, 7, 7, 7, 7, 7}, labels), 7.0 / 8.0);
  // Everything in one cluster: only one label can match.
  EXPECT_DOUBLE_EQ(CorrectlyClusteredFraction({0, 0, 0, 0, 0, 0, 0, 0}, labels), 0.5);
  // Over-split: the extra cluster's points are wrong.
  EXPECT_DOUBLE_EQ(CorrectlyClusteredFraction({0, 0, 2, 2, 1, 1, 1, 1}, labels), 6.0 / 8.0);
}

TEST(CorrectlyClusteredFraction, OutlierRules) {
  const std::vector<int32_t> labels = {0, 0, 1, 1, kUnassigned, kUnassigned};
  // Ground-truth outliers do not count, wherever they go.
  EXPECT_DOUBLE_EQ(CorrectlyClusteredFraction({0, 0, 1, 1, 0, kUnassigned}, labels), 1.0);
  // A labelled point left unassigned is wrong.
  EXPECT_DOUBLE_EQ(CorrectlyClusteredFraction({0, kUnassigned, 1, 1, 0, 0}, labels), 0.75);
}

TEST(CorrectlyClusteredFraction, RejectsBadInput) {
  EXPECT_THROW(CorrectlyClusteredFraction({0, 1}, {0}), std::invalid_argument);
  EXPECT_THROW(CorrectlyClusteredFraction({0}, {kUnassigned}), std::invalid_argument);
  EXPECT_THROW(CorrectlyClusteredFraction({-2}, {0}), std::invalid_argument);
}

}  // namespace
}  // namespace avc::cluster
