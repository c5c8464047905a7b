// The chaos benchmark's fault plan: the same for the same seed, every victim equally often
// (within one), every moment inside the allowed part of the scan.

#include "bench/chaos/chaos_plan.h"

#include <gtest/gtest.h>

#include <map>

namespace avc::bench {
namespace {

ChaosPlanOptions Plan(int trials, uint64_t seed) {
  ChaosPlanOptions options;
  options.trials = trials;
  options.seed = seed;
  options.scan_wall_s = 30;
  return options;
}

TEST(ChaosPlan, SameSeedSamePlanOtherSeedOtherPlan) {
  const auto a = PlanChaosFaults(Plan(20, 1));
  const auto b = PlanChaosFaults(Plan(20, 1));
  const auto c = PlanChaosFaults(Plan(20, 2));
  ASSERT_EQ(a.size(), 20u);
  bool differs = false;
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].victim, b[i].victim);
    EXPECT_EQ(a[i].at_s, b[i].at_s);
    differs |= a[i].victim != c[i].victim || a[i].at_s != c[i].at_s;
  }
  EXPECT_TRUE(differs);
}

TEST(ChaosPlan, VictimsAreBalancedAndMomentsInRange) {
  for (const int trials : {1, 6, 20, 37}) {
    const auto faults = PlanChaosFaults(Plan(trials, 7));
    std::map<std::string, int> count;
    for (const ChaosFault& fault : faults) {
      ++count[fault.victim];
      EXPECT_GE(fault.at_s, 0.05 * 30 - 1e-9);
      EXPECT_LE(fault.at_s, 0.90 * 30 + 1e-9);
    }
    const int fewest = trials / static_cast<int>(ChaosVictims().size());
    for (const std::string& victim : ChaosVictims()) {
      EXPECT_GE(count[victim], fewest) << victim << " in " << trials << " trials";
      EXPECT_LE(count[victim], fewest + 1) << victim << " in " << trials << " trials";
    }
  }
}

TEST(ChaosPlan, ShortScansAreNeverKilledInTheFirstSeconds) {
  ChaosPlanOptions options = Plan(12, 3);
  options.scan_wall_s = 3;
  for (const ChaosFault& fault : PlanChaosFaults(options)) EXPECT_GE(fault.at_s, 2.0);
}

TEST(ChaosPlan, RefusesAnEmptyPlan) {
  ChaosPlanOptions options = Plan(5, 1);
  options.victims.clear();
  EXPECT_THROW(PlanChaosFaults(options), std::invalid_argument);
  EXPECT_THROW(PlanChaosFaults(Plan(0, 1)), std::invalid_argument);
}

}  // namespace
}  // namespace avc::bench
