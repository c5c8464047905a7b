#include <gtest/gtest.h>

#include "bench/clustering/baselines/kmeans.h"
#include "bench/clustering/baselines/spectral_dense.h"
#include "bench/clustering/baselines/spectral_sparse.h"
#include "tests/bench/clustering/baselines/synthetic_sets.h"

namespace avc::cluster::baselines {
namespace {

using testing::Blobs;
using testing::ClusterCount;
using testing::ConcentricRings;
using testing::Purity;

TEST(DenseSpectralClustering, SeparatesBlobs) {
  const PointSet set = Blobs(3, 100, 2);
  DenseSpectralOptions options;
  options.clusters = 3;
  const Assignment assignment = DenseSpectralClustering(set, options);
  EXPECT_EQ(ClusterCount(assignment), 3);
  EXPECT_DOUBLE_EQ(Purity(assignment, set.labels), 1.0);
}

TEST(SparseSpectralClustering, SeparatesBlobs) {
  const PointSet set = Blobs(4, 75, 2);
  SparseSpectralOptions options;
  options.clusters = 4;
  const Assignment assignment = SparseSpectralClustering(set, options);
  EXPECT_EQ(ClusterCount(assignment), 4);
  EXPECT_DOUBLE_EQ(Purity(assignment, set.labels), 1.0);
}

// What spectral clustering is for: connectivity, where k-means can only cut by distance.
TEST(SpectralClustering, SeparatesConcentricRingsWhereKMeansCannot) {
  const PointSet set = ConcentricRings(150, 7);
  DenseSpectralOptions dense;
  dense.clusters = 2;
  SparseSpectralOptions sparse;
  sparse.clusters = 2;
  KMeansOptions kmeans;
  kmeans.clusters = 2;
  EXPECT_DOUBLE_EQ(Purity(DenseSpectralClustering(set, dense), set.labels), 1.0);
  EXPECT_DOUBLE_EQ(Purity(SparseSpectralClustering(set, sparse), set.labels), 1.0);
  EXPECT_LT(Purity(KMeansClustering(set, kmeans), set.labels), 0.9);
}

TEST(SpectralClustering, IsDeterministic) {
  const PointSet set = Blobs(5, 50, 11);
  DenseSpectralOptions dense;
  dense.clusters = 3;
  SparseSpectralOptions sparse;
  sparse.clusters = 3;
  EXPECT_EQ(DenseSpectralClustering(set, dense), DenseSpectralClustering(set, dense));
  EXPECT_EQ(SparseSpectralClustering(set, sparse), SparseSpectralClustering(set, sparse));
}

}  // namespace
}  // namespace avc::cluster::baselines
