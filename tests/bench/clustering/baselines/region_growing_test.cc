#include "bench/clustering/baselines/region_growing.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "tests/bench/clustering/baselines/synthetic_sets.h"

namespace avc::cluster::baselines {
namespace {

using testing::ClusterCount;
using testing::OrthogonalPatches;
using testing::Purity;

TEST(RegionGrowingClustering, FindsEachPlanarPatch) {
  const PointSet set = OrthogonalPatches(100, 1);
  const Assignment assignment = RegionGrowingClustering(set, {});
  EXPECT_EQ(ClusterCount(assignment), 3);
  EXPECT_EQ(std::count(assignment.begin(), assignment.end(), kUnassigned), 0);
  EXPECT_DOUBLE_EQ(Purity(assignment, set.labels), 1.0);
}

TEST(RegionGrowingClustering, UsesTheSetsNormals) {
  // Tilting the given normals of half of the z patch by 45 degrees must split that patch in two,
  // although its points (and so PCL's own normal estimate) are unchanged.
  PointSet set = OrthogonalPatches(100, 1);
  for (size_t i = 0; i < set.points.size(); ++i) {
    if (set.labels[i] == 2 && set.points[i].x() > 0) {
      set.normals[i] = Eigen::Vector3f(1, 0, 1).normalized();
    }
  }
  const Assignment assignment = RegionGrowingClustering(set, {});
  EXPECT_EQ(ClusterCount(assignment), 4);
  EXPECT_DOUBLE_EQ(Purity(assignment, set.labels), 1.0);
}

TEST(RegionGrowingClustering, LeavesSmallRegionsUnassigned) {
  const PointSet set = OrthogonalPatches(100, 1);
  RegionGrowingOptions options;
  options.min_cluster_size = 101;  // larger than every patch
  const Assignment assignment = RegionGrowingClustering(set, options);
  EXPECT_EQ(std::count(assignment.begin(), assignment.end(), kUnassigned),
            static_cast<long>(set.points.size()));
}

TEST(RegionGrowingClustering, IsDeterministic) {
  const PointSet set = OrthogonalPatches(80, 4);
  EXPECT_EQ(RegionGrowingClustering(set, {}), RegionGrowingClustering(set, {}));
}

}  // namespace
}  // namespace avc::cluster::baselines
