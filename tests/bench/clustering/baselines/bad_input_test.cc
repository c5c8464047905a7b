#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>
#include <string>

#include "bench/clustering/baselines/ipddp.h"
#include "bench/clustering/baselines/kmeans.h"
#include "bench/clustering/baselines/region_growing.h"
#include "bench/clustering/baselines/spectral_dense.h"
#include "bench/clustering/baselines/spectral_sparse.h"
#include "tests/bench/clustering/baselines/synthetic_sets.h"

namespace avc::cluster::baselines {
namespace {

// Runs `call` and returns the invalid_argument message ("" when nothing was thrown).
template <class Call>
std::string InvalidArgumentMessage(Call call) {
  try {
    call();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

void ExpectEveryMethodRejects(const PointSet& set, const std::string& fragment) {
  const std::string messages[] = {
      InvalidArgumentMessage([&] { KMeansClustering(set, {}); }),
      InvalidArgumentMessage([&] { IpddpClustering(set, {}); }),
      InvalidArgumentMessage([&] { DenseSpectralClustering(set, {}); }),
      InvalidArgumentMessage([&] { SparseSpectralClustering(set, {}); }),
      InvalidArgumentMessage([&] { RegionGrowingClustering(set, {}); })};
  for (const std::string& message : messages) {
    EXPECT_NE(message.find(fragment), std::string::npos) << "message: '" << message << "'";
  }
}

TEST(BaselineBadInput, EmptySetIsRejected) {
  PointSet set;
  set.name = "nothing";
  ExpectEveryMethodRejects(set, "'nothing' is empty");
}

TEST(BaselineBadInput, NonFinitePointIsNamed) {
  PointSet set = testing::Blobs(2, 20, 1);
  set.points[17].y() = std::numeric_limits<float>::quiet_NaN();
  ExpectEveryMethodRejects(set, "point 17 of set 'blobs' is not finite");
}

TEST(BaselineBadInput, RegionGrowingNeedsOneNormalPerPoint) {
  PointSet set = testing::OrthogonalPatches(20, 1);
  set.normals.pop_back();
  EXPECT_NE(InvalidArgumentMessage([&] { RegionGrowingClustering(set, {}); }).find("59 normals"),
            std::string::npos);
  set = testing::OrthogonalPatches(20, 1);
  set.normals[3] = Eigen::Vector3f::Zero();
  EXPECT_NE(InvalidArgumentMessage([&] { RegionGrowingClustering(set, {}); }).find("normal 3"),
            std::string::npos);
}

TEST(BaselineBadInput, ClusterCountOutsideRangeIsRejected) {
  const PointSet set = testing::Blobs(2, 5, 1);
  KMeansOptions kmeans;
  kmeans.clusters = 0;
  EXPECT_THROW(KMeansClustering(set, kmeans), std::invalid_argument);
  DenseSpectralOptions dense;
  dense.clusters = 11;
  EXPECT_THROW(DenseSpectralClustering(set, dense), std::invalid_argument);
  SparseSpectralOptions sparse;
  sparse.clusters = -1;
  EXPECT_THROW(SparseSpectralClustering(set, sparse), std::invalid_argument);
  IpddpOptions ipddp;
  ipddp.percentile = 0.5;
  EXPECT_THROW(IpddpClustering(set, ipddp), std::invalid_argument);
  RegionGrowingOptions growing;
  growing.smoothness_degrees = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(RegionGrowingClustering(set, growing), std::invalid_argument);
}

TEST(BaselineBadInput, TinySetsAreHandled) {
  // Fewer points than the default neighbourhoods (7, 10, 20): no crash, sensible output.
  const PointSet set = testing::Blobs(3, 1, 1);
  KMeansOptions kmeans;
  kmeans.clusters = 3;
  EXPECT_EQ(KMeansClustering(set, kmeans), (Assignment{0, 1, 2}));
  DenseSpectralOptions dense;
  dense.clusters = 2;
  EXPECT_EQ(testing::ClusterCount(DenseSpectralClustering(set, dense)), 2);
  SparseSpectralOptions sparse;
  sparse.clusters = 2;
  EXPECT_EQ(testing::ClusterCount(SparseSpectralClustering(set, sparse)), 2);
  EXPECT_EQ(IpddpClustering(set, {}), (Assignment{0, 0, 0}));
  EXPECT_EQ(RegionGrowingClustering(set, {}), Assignment(3, kUnassigned));
}

}  // namespace
}  // namespace avc::cluster::baselines
