#include "bench/clustering/baselines/ipddp.h"

#include <gtest/gtest.h>

#include "tests/bench/clustering/baselines/synthetic_sets.h"

namespace avc::cluster::baselines {
namespace {

using testing::Blobs;
using testing::ClusterCount;
using testing::Purity;

TEST(IpddpClustering, SplitsTwoSeparatedGroups) {
  const PointSet set = Blobs(2, 150, 4);
  IpddpOptions options;
  options.max_clusters = 2;
  const Assignment assignment = IpddpClustering(set, options);
  EXPECT_EQ(ClusterCount(assignment), 2);
  EXPECT_DOUBLE_EQ(Purity(assignment, set.labels), 1.0);
}

TEST(IpddpClustering, SplitsLargestGapsFirstOnFourBlobs) {
  const PointSet set = Blobs(4, 75, 6);
  IpddpOptions options;
  options.max_clusters = 4;
  const Assignment assignment = IpddpClustering(set, options);
  EXPECT_EQ(ClusterCount(assignment), 4);
  EXPECT_DOUBLE_EQ(Purity(assignment, set.labels), 1.0);
}

TEST(IpddpClustering, StopsWhenNoLeafMayBeSplit) {
  // Five points do not exceed min_sample_split = 5: one cluster whatever max_clusters says.
  PointSet set = Blobs(5, 1, 1);
  IpddpOptions options;
  options.max_clusters = 5;
  EXPECT_EQ(IpddpClustering(set, options), Assignment(5, 0));
  options.min_sample_split = 2;  // now the line of five points splits
  EXPECT_GT(ClusterCount(IpddpClustering(set, options)), 1);
}

TEST(IpddpClustering, IsDeterministic) {
  const PointSet set = Blobs(6, 40, 9);
  IpddpOptions options;
  options.max_clusters = 5;
  EXPECT_EQ(IpddpClustering(set, options), IpddpClustering(set, options));
}

}  // namespace
}  // namespace avc::cluster::baselines
