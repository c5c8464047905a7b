// The clusterer's work offline: two discs merge into their voxels and come out as two clusters
// with the outliers counted, and every kind of bad input ends in a problem that names it rather
// than an exception or an empty silence.

#include "services/clusterer/merge_and_cluster.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "core/ppr/octree_voxels.h"
#include "tests/services/clusterer/two_discs.h"

namespace avc::clusterer {
namespace {

using testing::kOutliers;
using testing::kVoxel;
using testing::MakeTwoDiscs;

TEST(MergeAndCluster, TwoDiscsBecomeTwoClustersOfMergedPoints) {
  const testing::TwoDiscs scene = MakeTwoDiscs();
  const mvs::MvsBounds proxy = ppr::OccupiedVoxelsFromBinary(scene.proxy_bt, kVoxel, "discs");
  const messages::ClustersContent content =
      MergeAndCluster(scene.points, proxy, {}, "discs-mvs", "discs-ppr");
  ASSERT_TRUE(content.problem.empty()) << content.problem;
  EXPECT_EQ(content.raw_points, 6000 + kOutliers);
  EXPECT_EQ(content.merged.outside_proxy, static_cast<uint64_t>(kOutliers));
  // A disc of radius 2 cm covers about 314 voxels of 2 mm; sparse rim voxels are dropped.
  EXPECT_GT(content.merged.size(), 450u);
  EXPECT_LT(content.merged.size(), 2 * 360u);
  EXPECT_EQ(content.num_clusters, 2);
  // Each disc is one cluster: the cluster of a point is decided by its height.
  std::set<std::pair<int32_t, bool>> pairs;
  for (size_t i = 0; i < content.merged.size(); ++i) {
    if (content.clusters[i] == cluster::kUnassigned) continue;
    pairs.insert({content.clusters[i], content.merged.cloud.positions[i].z() > 0.07f});
  }
  EXPECT_EQ(pairs.size(), 2u);
  const auto outliers =
      std::count(content.clusters.begin(), content.clusters.end(), cluster::kUnassigned);
  EXPECT_LT(outliers, 10);
  // Same input, same output.
  const messages::ClustersContent again =
      MergeAndCluster(scene.points, proxy, {}, "discs-mvs", "discs-ppr");
  EXPECT_EQ(again.clusters, content.clusters);
  EXPECT_EQ(again.merged.cloud.positions, content.merged.cloud.positions);
}

TEST(MergeAndCluster, BadInputEndsInAProblemNamingIt) {
  const testing::TwoDiscs scene = MakeTwoDiscs(200);
  const mvs::MvsBounds proxy = ppr::OccupiedVoxelsFromBinary(scene.proxy_bt, kVoxel, "discs");

  const auto problem_of = [&](const mvs::MvsPoints& points, const mvs::MvsBounds& bounds) {
    return MergeAndCluster(points, bounds, {}, "c1", "m1").problem;
  };
  EXPECT_NE(problem_of({}, proxy).find("MVS points 'c1' are empty"), std::string::npos);
  EXPECT_NE(problem_of(scene.points, {}).find("proxy 'm1' has no occupied voxel"),
            std::string::npos);

  mvs::MvsPoints nan_points = scene.points;
  nan_points.cloud.positions[5].x() = std::nanf("");
  const std::string nan_problem = problem_of(nan_points, proxy);
  EXPECT_NE(nan_problem.find("merging 'c1' into 'm1'"), std::string::npos) << nan_problem;

  mvs::MvsPoints no_normals = scene.points;
  no_normals.cloud.normals.clear();
  EXPECT_NE(problem_of(no_normals, proxy).find("normals"), std::string::npos);

  // Points that all fall outside the proxy: nothing to cluster, and it says so.
  mvs::MvsPoints far = scene.points;
  for (auto& p : far.cloud.positions) p.x() += 1.0f;
  const messages::ClustersContent none = MergeAndCluster(far, proxy, {}, "c1", "m1");
  EXPECT_NE(none.problem.find("too few to cluster"), std::string::npos) << none.problem;
  EXPECT_EQ(none.merged.outside_proxy, far.size());
}

}  // namespace
}  // namespace avc::clusterer
