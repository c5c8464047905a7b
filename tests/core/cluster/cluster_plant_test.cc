#include "core/cluster/cluster_plant.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <set>
#include <stdexcept>
#include <string>

#include "core/cluster/connected_components.h"
#include "core/cluster/scoring.h"
#include "tests/core/cluster/synthetic_sheets.h"

namespace avc::cluster {
namespace {

using testing::AddCylinder;
using testing::AddDisc;
using testing::AddNoise;
using testing::AddRectangle;

size_t DistinctClusters(const Assignment& assignment) {
  std::set<int32_t> ids;
  for (int32_t id : assignment) {
    if (id != kUnassigned) ids.insert(id);
  }
  return ids.size();
}

std::string ErrorOf(const PointSet& set) {
  try {
    ClusterPlant(set);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(ClusterPlant, TwoSeparatedPlanesGiveTwoClusters) {
  std::mt19937_64 rng(11);
  PointSet set;
  AddRectangle(&set, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0.06f, 0.06f, 1200, 0, rng);
  AddRectangle(&set, {0.075f, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0.06f, 0.06f, 1200, 1, rng);
  ClusterReport report;
  const Assignment assignment = ClusterPlant(set, {}, &report);
  EXPECT_EQ(DistinctClusters(assignment), 2u);
  EXPECT_EQ(report.clusters, 2u);
  EXPECT_DOUBLE_EQ(CorrectlyClusteredFraction(assignment, set.labels), 1.0);
  // Spacing of 1200 random points on 36 cm^2: median nearest neighbour ~ 0.47 * 1.7 mm.
  EXPECT_GT(report.spacing, 0.0005);
  EXPECT_LT(report.spacing, 0.0012);
  EXPECT_LT(report.noise, 0.0002);  // flat and noise-free: only sampling shows
}

TEST(ClusterPlant, StackedParallelPlanesAreSeparatedAlthoughWithinLinkRadius) {
  std::mt19937_64 rng(12);
  PointSet set;
  AddRectangle(&set, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0.05f, 0.05f, 1200, 0, rng);
  AddRectangle(&set, {0.01f, 0, 0.003f}, {1, 0, 0}, {0, 1, 0}, 0.05f, 0.05f, 1200, 1, rng);
  ClusterReport report;
  const Assignment assignment = ClusterPlant(set, {}, &report);
  ASSERT_GT(report.link_radius, 0.003);  // the layers are closer than the link radius
  EXPECT_DOUBLE_EQ(CorrectlyClusteredFraction(assignment, set.labels), 1.0);
}

// The bisector test: two points of stacked sheets facing the same way (3 mm apart, 8 mm across)
// pass the per-point slope test but not the bisector one; two points 8 mm apart on a sheet
// curled at a 15 mm radius (normals 31 deg apart, chord 2.1 mm off each tangent plane) pass both.
TEST(LinkRule, BisectorSeparatesStackedSheetsNotCurledOnes) {
  const float r = 0.015f, half = 0.26f;  // half the angle between the curled points' normals
  const std::vector<Eigen::Vector3f> points = {{0, 0, 0},
                                               {0.008f, 0, 0.003f},  // stacked
                                               {-r * std::sin(half), 0, r * std::cos(half)},
                                               {r * std::sin(half), 0, r * std::cos(half)}};
  const std::vector<Eigen::Vector3f> normals = {Eigen::Vector3f::UnitZ(), Eigen::Vector3f::UnitZ(),
                                                points[2] / r, points[3] / r};
  LinkRule rule;
  rule.radius = 0.012f;
  rule.normals = &normals;
  rule.allowance = 0.0006f;
  EXPECT_TRUE(rule.Linked(points, 0, 1));  // slope 0.35 < 0.5: the old rule links them
  EXPECT_TRUE(rule.Linked(points, 2, 3));
  rule.mean_slope = kSameSurfaceMeanSlope;
  EXPECT_FALSE(rule.Linked(points, 0, 1));
  EXPECT_TRUE(rule.Linked(points, 2, 3));
}

TEST(ClusterPlant, BentSheetIsSplitByTheNormalConstraint) {
  std::mt19937_64 rng(13);
  PointSet set;
  // Two 6 x 6 cm planes sharing the edge x = 0 at 90 degrees: one connected, non-flat sheet.
  AddRectangle(&set, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0.06f, 0.06f, 1500, 0, rng);
  AddRectangle(&set, {0, 0, 0}, {0, 1, 0}, {0, 0, 1}, 0.06f, 0.06f, 1500, 1, rng);
  ClusterReport report;
  const Assignment assignment = ClusterPlant(set, {}, &report);
  EXPECT_EQ(report.initial_components, 1u);
  EXPECT_GE(report.normal_splits, 1u);
  EXPECT_EQ(DistinctClusters(assignment), 2u);
  EXPECT_GE(CorrectlyClusteredFraction(assignment, set.labels), 0.995);
}

TEST(ClusterPlant, FlatLeafIsNotSplit) {
  std::mt19937_64 rng(14);
  PointSet set;
  AddDisc(&set, {0, 0, 0}, 0.05f, 3000, 0, rng);
  ClusterReport report;
  const Assignment assignment = ClusterPlant(set, {}, &report);
  EXPECT_EQ(report.normal_splits + report.separation_splits + report.neck_splits, 0u);
  EXPECT_EQ(DistinctClusters(assignment), 1u);
}

TEST(ClusterPlant, TouchingCoplanarLeavesAreCutAtTheirNeck) {
  std::mt19937_64 rng(21);
  PointSet set;
  // Two coplanar discs overlapping by 1 mm: one flat connected component, no gap, same normals.
  AddDisc(&set, {0, 0, 0}, 0.03f, 1500, 0, rng);
  AddDisc(&set, {0.059f, 0, 0}, 0.03f, 1500, 1, rng);
  ClusterReport report;
  const Assignment assignment = ClusterPlant(set, {}, &report);
  EXPECT_EQ(report.initial_components, 1u);
  EXPECT_GE(report.neck_splits, 1u);
  EXPECT_EQ(DistinctClusters(assignment), 2u);
  EXPECT_GE(CorrectlyClusteredFraction(assignment, set.labels), 0.98);

  ClusterOptions without;
  without.max_neck_ratio = 0;
  EXPECT_EQ(DistinctClusters(ClusterPlant(set, without)), 1u);
}

TEST(ClusterPlant, ElongatedLeafIsNotCutAtItsWidth) {
  std::mt19937_64 rng(22);
  PointSet set;
  // An elliptic blade three times longer than wide: a cut across it is as long as the blade is
  // wide, no neck. (A uniform strip six times longer than wide is at the limit: see
  // cluster_plant.h.)
  AddDisc(&set, {0, 0, 0}, 0.03f, 3000, 0, rng);
  for (Eigen::Vector3f& p : set.points) p.x() *= 3.0f;
  ClusterReport report;
  const Assignment assignment = ClusterPlant(set, {}, &report);
  EXPECT_EQ(report.neck_splits, 0u);
  EXPECT_EQ(DistinctClusters(assignment), 1u);
}

// Two 6 x 3 cm sheets that pass through each other along the middle of both at `angle` (an X
// seen end-on), with the noise of the Table 2 sets: connected, no gap, no neck, and too little
// normal gain for the normal constraint.
PointSet CrossingSheets(float angle, std::mt19937_64& rng) {
  PointSet set;
  const float half = 0.015f;
  const Eigen::Vector3f across(0, std::cos(angle), std::sin(angle));
  AddRectangle(&set, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0.06f, 2 * half, 1500, 0, rng);
  AddRectangle(&set, Eigen::Vector3f(0.005f, half, 0) - half * across, {1, 0, 0}, across, 0.06f,
               2 * half, 1500, 1, rng);
  AddNoise(&set, 0.0001f, 0.05f, rng);
  return set;
}

TEST(ClusterPlant, CrossingSheetsAreSeparatedWhereTheirNormalsJump) {
  std::mt19937_64 rng(23);
  const PointSet set = CrossingSheets(static_cast<float>(25.0 * std::numbers::pi / 180.0), rng);
  ClusterReport report;
  const Assignment assignment = ClusterPlant(set, {}, &report);
  EXPECT_EQ(report.initial_components, 1u);
  EXPECT_EQ(report.normal_splits, 0u);
  EXPECT_GE(report.sheet_splits, 1u);
  EXPECT_EQ(DistinctClusters(assignment), 2u);
  EXPECT_GE(CorrectlyClusteredFraction(assignment, set.labels), 0.99);

  ClusterOptions without;
  without.max_sheet_edge_bias = 0;
  EXPECT_EQ(DistinctClusters(ClusterPlant(set, without)), 1u);
}

TEST(ClusterPlant, SheetFoldedAtTheSameAngleIsNotCutAtItsFold) {
  std::mt19937_64 rng(24);
  // One sheet folded along a line by the same 25 degrees (a leaf at its midrib): the normals jump
  // there too, but both halves end at the fold instead of passing through each other.
  PointSet set;
  const float angle = static_cast<float>(25.0 * std::numbers::pi / 180.0);
  AddRectangle(&set, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0.06f, 0.03f, 1500, 0, rng);
  AddRectangle(&set, {0, 0.03f, 0}, {1, 0, 0}, {0, std::cos(angle), std::sin(angle)}, 0.06f, 0.03f,
               1500, 0, rng);
  AddNoise(&set, 0.0001f, 0.05f, rng);
  ClusterReport report;
  const Assignment assignment = ClusterPlant(set, {}, &report);
  EXPECT_EQ(report.sheet_splits, 0u);
  EXPECT_EQ(DistinctClusters(assignment), 1u);
}

TEST(ClusterPlant, LeafOnAStemGivesLeafAndStem) {
  std::mt19937_64 rng(15);
  PointSet set;
  // A horizontal leaf resting on the top of a vertical stem (the stem touches it).
  AddDisc(&set, {0, 0, 0.08f}, 0.04f, 2000, 0, rng);
  AddCylinder(&set, {0.02f, 0, 0}, 0.003f, 0.08f, 600, 1, rng);
  ClusterReport report;
  const Assignment assignment = ClusterPlant(set, {}, &report);
  EXPECT_EQ(report.initial_components, 1u);
  EXPECT_EQ(DistinctClusters(assignment), 2u);
  EXPECT_GE(CorrectlyClusteredFraction(assignment, set.labels), 0.99);
}

// A thick stem sampled sparsely (seed 15's set D: 116 points on a 16 mm wide, 75 mm stem among
// leaves 2.6 mm apart). Its normals gain from a split into opposite lengthwise strips, which fall
// apart into four pieces: the normal constraint must not take that as two planes at a fold.
TEST(ClusterPlant, SparseThickStemStaysOneCluster) {
  ClusterOptions options;
  options.spacing = 0.0026;  // the leaves' spacing, as in set D
  options.noise = 0.00016;
  int whole = 0;
  const int trials = 20;
  for (int trial = 0; trial < trials; ++trial) {
    std::mt19937_64 rng(100 + trial);
    PointSet set;
    AddCylinder(&set, {0, 0, 0}, 0.008f, 0.075f, 116, 0, rng);
    AddNoise(&set, 0.0002f, 0.05f, rng);
    const Assignment assignment = ClusterPlant(set, options);
    whole += DistinctClusters(assignment) == 1 &&
             CorrectlyClusteredFraction(assignment, set.labels) == 1.0;
  }
  EXPECT_EQ(whole, trials);
}

TEST(ClusterPlant, IsolatedPointsAreOutliers) {
  std::mt19937_64 rng(16);
  PointSet set;
  AddDisc(&set, {0, 0, 0}, 0.04f, 1500, 0, rng);
  set.points.push_back({0.2f, 0.2f, 0.2f});
  set.normals.push_back(Eigen::Vector3f::UnitX());
  ClusterReport report;
  const Assignment assignment = ClusterPlant(set, {}, &report);
  EXPECT_EQ(assignment.back(), kUnassigned);
  EXPECT_EQ(report.outliers, 1u);
}

TEST(ClusterPlant, SameInputSameAssignment) {
  std::mt19937_64 rng(17);
  PointSet set;
  AddRectangle(&set, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0.06f, 0.06f, 1500, 0, rng);
  AddRectangle(&set, {0, 0, 0}, {0, 1, 0}, {0, 0, 1}, 0.06f, 0.06f, 1500, 1, rng);
  EXPECT_EQ(ClusterPlant(set), ClusterPlant(set));
}

TEST(ClusterPlant, GivenScalesAreUsed) {
  std::mt19937_64 rng(18);
  PointSet set;
  AddDisc(&set, {0, 0, 0}, 0.04f, 1000, 0, rng);
  ClusterOptions options;
  options.spacing = 0.002;
  options.noise = 0.0001;
  ClusterReport report;
  ClusterPlant(set, options, &report);
  EXPECT_DOUBLE_EQ(report.spacing, 0.002);
  EXPECT_DOUBLE_EQ(report.noise, 0.0001);
  EXPECT_NEAR(report.link_radius, options.link_factor * 0.002, 1e-9);
}

TEST(ClusterPlant, BadInputIsRejectedWithAClearMessage) {
  PointSet empty;
  empty.name = "empty";
  EXPECT_NE(ErrorOf(empty).find("at least 3 points, got 0"), std::string::npos) << ErrorOf(empty);

  PointSet two;
  two.points = {{0, 0, 0}, {1, 0, 0}};
  two.normals = {{0, 0, 1}, {0, 0, 1}};
  EXPECT_NE(ErrorOf(two).find("got 2"), std::string::npos);

  PointSet nan_point;
  nan_point.name = "slice";
  nan_point.points = {{0, 0, 0}, {std::numeric_limits<float>::quiet_NaN(), 0, 0}, {0, 1, 0}};
  nan_point.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  EXPECT_NE(ErrorOf(nan_point).find("'slice': point 1 is not finite"), std::string::npos)
      << ErrorOf(nan_point);

  PointSet missing = nan_point;
  missing.points[1] = {1, 0, 0};
  missing.normals.clear();
  EXPECT_NE(ErrorOf(missing).find("0 normals for 3 points"), std::string::npos) << ErrorOf(missing);

  PointSet zero_normal = missing;
  zero_normal.normals = {{0, 0, 1}, {0, 0, 0}, {0, 0, 1}};
  EXPECT_NE(ErrorOf(zero_normal).find("normal 1 is zero"), std::string::npos);

  PointSet good = missing;
  good.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  ClusterOptions bad_options;
  bad_options.link_factor = 0;
  EXPECT_THROW(ClusterPlant(good, bad_options), std::invalid_argument);
  for (double ClusterOptions::*field :
       {&ClusterOptions::neck_elevation_factor, &ClusterOptions::neck_max_boundary_shift}) {
    ClusterOptions negative;
    negative.*field = -1;
    EXPECT_THROW(ClusterPlant(good, negative), std::invalid_argument);
  }
}

}  // namespace
}  // namespace avc::cluster
