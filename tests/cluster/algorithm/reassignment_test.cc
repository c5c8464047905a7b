// Step 3's last move (core/cluster/reassignment.h): parts of a cluster its own links no longer
// reach join the cluster they are linked to.

#include "core/cluster/reassignment.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "core/cluster/neighbour_lists.h"
#include "core/cluster/point_set.h"

namespace avc::cluster {
namespace {

// Points of a regular grid in the plane z = height (pitch 1, normals +z), x from x0 for nx
// columns, y from 0 for ny rows, all in cluster id.
void AddGrid(float x0, int nx, int ny, float height, int32_t id,
             std::vector<Eigen::Vector3f>* points, std::vector<Eigen::Vector3f>* normals,
             std::vector<int32_t>* cluster_of) {
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      points->emplace_back(x0 + static_cast<float>(i), static_cast<float>(j), height);
      normals->push_back(Eigen::Vector3f::UnitZ());
      cluster_of->push_back(id);
    }
  }
}

TEST(RejoinStrandedParts, APartItsClusterNoLongerReachesJoinsTheClusterItLiesIn) {
  std::vector<Eigen::Vector3f> points;
  std::vector<Eigen::Vector3f> normals;
  std::vector<int32_t> cluster_of;
  AddGrid(0, 10, 10, 0, 0, &points, &normals, &cluster_of);   // cluster 0: x 0-9
  AddGrid(30, 10, 10, 0, 1, &points, &normals, &cluster_of);  // cluster 1: x 30-39
  const size_t stranded = points.size();
  AddGrid(40, 2, 2, 0, 0, &points, &normals, &cluster_of);  // 4 points of 0 beside 1
  const size_t floating = points.size();
  AddGrid(60, 2, 2, 20, 0, &points, &normals, &cluster_of);  // 4 points of 0 linked to none
  const size_t small_cluster = points.size();
  AddGrid(80, 2, 2, 0, 2, &points, &normals, &cluster_of);  // cluster 2: only 4 points
  const size_t stacked = points.size();
  AddGrid(33, 2, 2, 1.5f, 0, &points, &normals, &cluster_of);  // 4 of 0 stacked 1.5 over 1

  const float radius = 2.5f;
  const PointGrid grid(points, radius);
  LinkRule link;
  link.radius = radius;
  link.normals = &normals;
  const NeighbourLists neighbours(grid, points, link);
  std::vector<int32_t> scratch(points.size(), -1);
  std::vector<int32_t> result = cluster_of;
  EXPECT_EQ(RejoinStrandedParts(neighbours, 13, &scratch, &result), 4u);

  for (size_t i = stranded; i < floating; ++i) EXPECT_EQ(result[i], 1) << i;
  for (size_t i = 0; i < points.size(); ++i) {
    if (i < stranded || i >= floating) {
      EXPECT_EQ(result[i], cluster_of[i]) << i;
    }
  }
  // Parts linked to no other cluster stay: in the air, or stacked over another cluster (near,
  // but the offset runs along the normals); so does a cluster that is small but whole.
  EXPECT_EQ(result[floating], 0);
  EXPECT_EQ(result[stacked], 0);
  EXPECT_EQ(result[small_cluster], 2);
  EXPECT_EQ(std::count(scratch.begin(), scratch.end(), -1), static_cast<long>(scratch.size()));
}

TEST(RejoinStrandedParts, PartsAsLargeAsARealClusterStay) {
  std::vector<Eigen::Vector3f> points;
  std::vector<Eigen::Vector3f> normals;
  std::vector<int32_t> cluster_of;
  AddGrid(0, 10, 10, 0, 0, &points, &normals, &cluster_of);
  AddGrid(30, 10, 10, 0, 1, &points, &normals, &cluster_of);
  AddGrid(40, 4, 4, 0, 0, &points, &normals, &cluster_of);  // 16 points of 0 beside 1
  const float radius = 2.5f;
  const PointGrid grid(points, radius);
  LinkRule link;
  link.radius = radius;
  link.normals = &normals;
  const NeighbourLists neighbours(grid, points, link);
  std::vector<int32_t> scratch(points.size(), -1);
  std::vector<int32_t> result = cluster_of;
  EXPECT_EQ(RejoinStrandedParts(neighbours, 13, &scratch, &result), 0u);
  EXPECT_EQ(result, cluster_of);
}

}  // namespace
}  // namespace avc::cluster
