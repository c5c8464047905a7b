#include "bench/clustering/clustering_comparison.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "bench/clustering/clustering_table.h"
#include "bench/clustering/compared_methods.h"
#include "tests/bench/clustering/baselines/synthetic_sets.h"

namespace avc::bench {
namespace {

using cluster::Assignment;
using cluster::PointSet;

// A stand-in for the paper's method: the ground truth itself (accuracy 1 under any fair score).
Assignment Oracle(const PointSet& set) { return set.labels; }

// A stand-in score: fraction of points whose id equals their label.
double SameIdFraction(const Assignment& assignment, const std::vector<int32_t>& labels) {
  size_t same = 0;
  for (size_t i = 0; i < labels.size(); ++i) same += assignment[i] == labels[i];
  return static_cast<double>(same) / static_cast<double>(labels.size());
}

ComparisonOptions OptionsWithSimpleCallbacks() {
  ComparisonOptions options;
  options.ours = Oracle;
  options.ours_name = "oracle";
  options.score = SameIdFraction;
  options.repeats = 2;
  options.dense_spectral_max_points = 250;
  return options;
}

TEST(ClusteringComparison, ReportsEveryMethodOnEverySet) {
  const std::vector<PointSet> sets = {cluster::testing::Blobs(2, 100, 1),
                                      cluster::testing::OrthogonalPatches(100, 2)};
  const nlohmann::json report = RunClusteringComparison(sets, OptionsWithSimpleCallbacks());

  EXPECT_EQ(report["benchmark"], "clustering");
  EXPECT_EQ(report["repeats"], 2);
  ASSERT_EQ(report["sets"].size(), 2u);
  EXPECT_EQ(report["sets"][0]["points"], 200);
  EXPECT_EQ(report["sets"][0]["clusters"], 2);
  EXPECT_EQ(report["sets"][1]["clusters"], 3);
  const std::vector<std::string> names = {
      "oracle",           kKMeansName,         kIpddpName,
      kDenseSpectralName, kSparseSpectralName, kRegionGrowingName};
  ASSERT_EQ(report["methods"].size(), names.size());
  for (size_t m = 0; m < names.size(); ++m) {
    const nlohmann::json& method = report["methods"][m];
    EXPECT_EQ(method["name"], names[m]);
    ASSERT_EQ(method["results"].size(), 2u);
    for (size_t s = 0; s < 2; ++s) {
      const nlohmann::json& result = method["results"][s];
      EXPECT_EQ(result["set"], sets[s].name);
      if (names[m] == kDenseSpectralName && s == 1) {
        EXPECT_EQ(result["status"], "skipped");  // 300 points > cap 250
        continue;
      }
      ASSERT_EQ(result["status"], "ok") << names[m] << " on " << sets[s].name;
      EXPECT_EQ(result["runs_ms"].size(), 2u);
      EXPECT_GE(result["median_ms"].get<double>(), 0.0);
      EXPECT_TRUE(result["repeatable"].get<bool>());
      EXPECT_GE(result["accuracy"].get<double>(), 0.0);
      EXPECT_LE(result["accuracy"].get<double>(), 1.0);
    }
  }
  EXPECT_DOUBLE_EQ(report["methods"][0]["results"][0]["accuracy"].get<double>(), 1.0);
  EXPECT_EQ(report["methods"][0]["results"][1]["clusters_found"], 3);
  ASSERT_EQ(report["speed_ratios"].size(), 2u);
  EXPECT_GT(report["speed_ratios"][0]["dense_spectral_over_ours"].get<double>(), 0.0);
  EXPECT_TRUE(report["speed_ratios"][1]["dense_spectral_over_ours"].is_null());
  EXPECT_GT(report["speed_ratios"][1]["sparse_spectral_over_ours"].get<double>(), 0.0);
}

TEST(ClusteringComparison, MethodErrorsAreReportedNotThrown) {
  ComparisonOptions options = OptionsWithSimpleCallbacks();
  options.ours = [](const PointSet&) -> Assignment { throw std::runtime_error("broken method"); };
  const nlohmann::json report =
      RunClusteringComparison({cluster::testing::Blobs(2, 30, 1)}, options);
  EXPECT_EQ(report["methods"][0]["results"][0]["status"], "error");
  EXPECT_EQ(report["methods"][0]["results"][0]["reason"], "broken method");
  EXPECT_TRUE(report["speed_ratios"][0]["dense_spectral_over_ours"].is_null());
  EXPECT_NE(FormatClusteringTable(report).find("broken method"), std::string::npos);
}

TEST(ClusteringComparison, UnlabelledSetNeedsExplicitK) {
  PointSet set = cluster::testing::Blobs(2, 30, 1);
  set.labels.clear();
  EXPECT_THROW(RunClusteringComparison({set}, OptionsWithSimpleCallbacks()), std::invalid_argument);
  ComparisonOptions options = OptionsWithSimpleCallbacks();
  options.ours = nullptr;  // no "ours" row, no ratios
  options.clusters = 2;
  options.repeats = 1;
  const nlohmann::json report = RunClusteringComparison({set}, options);
  EXPECT_EQ(report["methods"].size(), 5u);
  EXPECT_TRUE(report["methods"][0]["results"][0]["accuracy"].is_null());
  EXPECT_TRUE(report["speed_ratios"][0]["sparse_spectral_over_ours"].is_null());
}

TEST(ClusteringTable, PrintsOneRowPerMethodAndTheRatios) {
  const std::vector<PointSet> sets = {cluster::testing::Blobs(2, 100, 1),
                                      cluster::testing::OrthogonalPatches(100, 2)};
  const std::string table =
      FormatClusteringTable(RunClusteringComparison(sets, OptionsWithSimpleCallbacks()));
  EXPECT_NE(table.find("blobs (200 pts, K=2)"), std::string::npos) << table;
  EXPECT_NE(table.find("patches (300 pts, K=3)"), std::string::npos) << table;
  EXPECT_NE(table.find("oracle"), std::string::npos);
  EXPECT_NE(table.find("100.0% / "), std::string::npos);
  EXPECT_NE(table.find("skipped"), std::string::npos);
  EXPECT_NE(table.find("300 points > cap 250"), std::string::npos);
  EXPECT_NE(table.find("time dense spectral / ours"), std::string::npos);
  EXPECT_EQ(std::count(table.begin(), table.end(), '\n'), 1 + 6 + 2 + 2);  // + notes
  EXPECT_THROW(FormatClusteringTable(nlohmann::json::object()), std::invalid_argument);
}

}  // namespace
}  // namespace avc::bench
