#include "bench/clustering/baselines/kmeans.h"

#include <gtest/gtest.h>

#include "tests/bench/clustering/baselines/synthetic_sets.h"

namespace avc::cluster::baselines {
namespace {

using testing::Blobs;
using testing::ClusterCount;
using testing::Purity;

TEST(KMeansClustering, SeparatesBlobsWithTrueK) {
  const PointSet set = Blobs(4, 75, 3);
  KMeansOptions options;
  options.clusters = 4;
  const Assignment assignment = KMeansClustering(set, options);
  ASSERT_EQ(assignment.size(), set.points.size());
  EXPECT_EQ(ClusterCount(assignment), 4);
  EXPECT_DOUBLE_EQ(Purity(assignment, set.labels), 1.0);
}

TEST(KMeansClustering, SameInputAndSeedGiveSameAssignment) {
  const PointSet set = Blobs(5, 60, 8);
  KMeansOptions options;
  options.clusters = 3;  // wrong K: many local optima, so the seed matters
  options.restarts = 1;
  EXPECT_EQ(KMeansClustering(set, options), KMeansClustering(set, options));
}

TEST(KMeansClustering, IdsAreNumberedByFirstPoint) {
  const PointSet set = Blobs(3, 50, 5);
  KMeansOptions options;
  options.clusters = 3;
  const Assignment assignment = KMeansClustering(set, options);
  EXPECT_EQ(assignment.front(), 0);
  EXPECT_EQ(assignment[50], 1);
  EXPECT_EQ(assignment[100], 2);
}

}  // namespace
}  // namespace avc::cluster::baselines
