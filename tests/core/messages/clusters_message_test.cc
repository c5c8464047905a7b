// Clusters on the bus: the clusters_t round trip is exact through LCM bytes, an empty answer with
// a problem travels too, and malformed messages or content are refused naming the cloud and the
// field or point.

#include "core/messages/clusters_message.h"

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>
#include <string>

#include "tests/support/test_support.h"

namespace avc::messages {
namespace {

ClustersContent RandomClusters(size_t count, int32_t clusters, uint32_t seed) {
  std::mt19937 rng(seed);
  const auto unit = [&] { return static_cast<float>(rng() >> 8) / static_cast<float>(1 << 24); };
  ClustersContent content;
  content.cloud_id = "scan-mvs-1";
  content.map_id = "scan-ppr";
  content.num_clusters = clusters;
  content.raw_points = static_cast<int64_t>(10 * count);
  merge::MergedPoints& merged = content.merged;
  merged.voxel_size = 0.002;
  merged.outside_proxy = 17;
  merged.in_sparse_voxels = 5;
  for (size_t i = 0; i < count; ++i) {
    // One draw per statement: the order of a call's arguments is unspecified.
    Eigen::Vector3i voxel;
    for (int k = 0; k < 2; ++k) voxel[k] = static_cast<int>(rng() % 200) - 100;
    voxel.z() = static_cast<int>(rng() % 90);
    merged.voxels.push_back(voxel);
    merged.cloud.positions.push_back(((voxel.cast<float>().array() + unit()) * 0.002f).matrix());
    Eigen::Vector3f normal(0, 0, 1);
    for (int k = 0; k < 2; ++k) normal[k] = unit() - 0.5f;
    merged.cloud.normals.push_back(normal.normalized());
    Eigen::Matrix<uint8_t, 3, 1> colour;
    for (int k = 0; k < 3; ++k) colour[k] = static_cast<uint8_t>(rng());
    merged.cloud.colors.push_back(colour);
    merged.confidence.push_back(unit());
    merged.point_counts.push_back(4 + rng() % 30);
    content.clusters.push_back(static_cast<int32_t>(rng() % (clusters + 1)) - 1);
  }
  return content;
}

avc::clusters_t ThroughLcm(const avc::clusters_t& message) {
  const std::string bytes = testing::Encode(message);
  avc::clusters_t decoded;
  EXPECT_EQ(decoded.decode(bytes.data(), 0, static_cast<int>(bytes.size())),
            static_cast<int>(bytes.size()));
  return decoded;
}

template <class Fn>
std::string ErrorOf(Fn&& fn) {
  try {
    fn();
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

TEST(ClustersMessage, RoundTripIsExact) {
  const ClustersContent content = RandomClusters(500, 7, 3);
  const avc::clusters_t message = ClustersToMessage(content);
  EXPECT_EQ(message.points.num_points, 500);
  EXPECT_EQ(message.outside_proxy, 17);
  int32_t outliers = 0;
  for (const int32_t id : content.clusters) outliers += id == cluster::kUnassigned;
  EXPECT_GT(outliers, 0);
  EXPECT_EQ(message.clustering_outliers, outliers);

  const ClustersContent back = ClustersFromMessage(ThroughLcm(message));
  EXPECT_EQ(back.cloud_id, content.cloud_id);
  EXPECT_EQ(back.map_id, content.map_id);
  EXPECT_EQ(back.num_clusters, 7);
  EXPECT_EQ(back.raw_points, content.raw_points);
  EXPECT_EQ(back.merged.voxel_size, 0.002);
  EXPECT_EQ(back.merged.in_sparse_voxels, 5u);
  EXPECT_EQ(back.clusters, content.clusters);
  EXPECT_EQ(back.merged.voxels, content.merged.voxels);
  EXPECT_EQ(back.merged.point_counts, content.merged.point_counts);
  EXPECT_EQ(back.merged.confidence, content.merged.confidence);
  EXPECT_EQ(back.merged.cloud.positions, content.merged.cloud.positions);
  EXPECT_EQ(back.merged.cloud.normals, content.merged.cloud.normals);
  EXPECT_EQ(back.merged.cloud.colors, content.merged.cloud.colors);
  // Same content, same bytes.
  EXPECT_EQ(testing::Encode(ClustersToMessage(content)), testing::Encode(message));
}

TEST(ClustersMessage, AnEmptyAnswerCarriesItsProblem) {
  ClustersContent content;
  content.cloud_id = "scan-mvs-2";
  content.problem = "no plant proxy received yet";
  const ClustersContent back = ClustersFromMessage(ThroughLcm(ClustersToMessage(content)));
  EXPECT_EQ(back.problem, content.problem);
  EXPECT_EQ(back.merged.size(), 0u);
  EXPECT_EQ(back.num_clusters, 0);
}

TEST(ClustersMessage, BadContentAndMessagesAreRefusedByName) {
  ClustersContent content = RandomClusters(20, 3, 1);
  content.clusters[4] = 3;
  EXPECT_NE(ErrorOf([&] { ClustersToMessage(content); }).find("point 4 has cluster 3 of 3"),
            std::string::npos);
  content = RandomClusters(20, 3, 1);
  content.merged.voxels.pop_back();
  EXPECT_NE(ErrorOf([&] { ClustersToMessage(content); }).find("19 voxels"), std::string::npos);

  const avc::clusters_t good = ClustersToMessage(RandomClusters(20, 3, 1));
  avc::clusters_t bad = good;
  bad.points.data.pop_back();
  EXPECT_NE(ErrorOf([&] { ClustersFromMessage(bad); }).find("clusters 'scan-mvs-1'"),
            std::string::npos);
  bad = good;
  bad.points.fields.erase(bad.points.fields.begin() + 10);  // "cluster"
  bad.points.num_fields = static_cast<int32_t>(bad.points.fields.size());
  EXPECT_NE(ErrorOf([&] { ClustersFromMessage(bad); }).find("no field 'cluster'"),
            std::string::npos);
  bad = good;
  bad.num_clusters = 1;
  EXPECT_NE(ErrorOf([&] { ClustersFromMessage(bad); }).find("has cluster"), std::string::npos);
  bad = good;
  bad.voxel_size = std::nan("");
  EXPECT_NE(ErrorOf([&] { ClustersFromMessage(bad); }).find("voxel size"), std::string::npos);
}

}  // namespace
}  // namespace avc::messages
