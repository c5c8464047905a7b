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

// Labelled points with normals.
struct Cloud {
  std::vector<Eigen::Vector3f> points;
  std::vector<Eigen::Vector3f> normals;
  std::vector<int32_t> cluster_of;
};

// Points of a regular grid in the plane z = height (pitch 1, normals +z), x from x0 for nx
// columns, y from 0 for ny rows, all in cluster id.
void AddGrid(float x0, int nx, int ny, float height, int32_t id, Cloud* cloud) {
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      cloud->points.emplace_back(x0 + static_cast<float>(i), static_cast<float>(j), height);
      cloud->normals.push_back(Eigen::Vector3f::UnitZ());
      cloud->cluster_of.push_back(id);
    }
  }
}

// The cloud's clusters after RejoinStrandedParts (links within 2.5, the default slopes, parts
// below 13 points); *moved receives its count. The scratch must come back all -1.
std::vector<int32_t> Rejoined(const Cloud& cloud, size_t* moved) {
  const float radius = 2.5f;
  const PointGrid grid(cloud.points, radius);
  LinkRule link;
  link.radius = radius;
  link.normals = &cloud.normals;
  const NeighbourLists neighbours(grid, cloud.points, link);
  std::vector<int32_t> scratch(cloud.points.size(), -1);
  std::vector<int32_t> result = cloud.cluster_of;
  *moved = RejoinStrandedParts(neighbours, 13, &scratch, &result);
  EXPECT_EQ(std::count(scratch.begin(), scratch.end(), -1), static_cast<long>(scratch.size()));
  return result;
}

TEST(RejoinStrandedParts, APartItsClusterNoLongerReachesJoinsTheClusterItLiesIn) {
  Cloud cloud;
  AddGrid(0, 10, 10, 0, 0, &cloud);   // cluster 0: x 0-9
  AddGrid(30, 10, 10, 0, 1, &cloud);  // cluster 1: x 30-39
  const size_t stranded = cloud.points.size();
  AddGrid(40, 2, 2, 0, 0, &cloud);  // 4 points of 0 beside 1
  const size_t floating = cloud.points.size();
  AddGrid(60, 2, 2, 20, 0, &cloud);  // 4 points of 0 linked to none
  const size_t small_cluster = cloud.points.size();
  AddGrid(80, 2, 2, 0, 2, &cloud);  // cluster 2: only 4 points
  const size_t stacked = cloud.points.size();
  AddGrid(33, 2, 2, 1.5f, 0, &cloud);  // 4 of 0 stacked 1.5 over 1

  size_t moved = 0;
  const std::vector<int32_t> result = Rejoined(cloud, &moved);
  EXPECT_EQ(moved, 4u);
  for (size_t i = 0; i < result.size(); ++i) {
    const bool beside = i >= stranded && i < floating;
    EXPECT_EQ(result[i], beside ? 1 : cloud.cluster_of[i]) << i;
  }
  // Parts linked to no other cluster stay: in the air, or stacked over another cluster (near,
  // but the offset runs along the normals); so does a cluster that is small but whole.
  EXPECT_EQ(result[floating], 0);
  EXPECT_EQ(result[stacked], 0);
  EXPECT_EQ(result[small_cluster], 2);
}

TEST(RejoinStrandedParts, PartsAsLargeAsARealClusterStay) {
  Cloud cloud;
  AddGrid(0, 10, 10, 0, 0, &cloud);
  AddGrid(30, 10, 10, 0, 1, &cloud);
  AddGrid(40, 4, 4, 0, 0, &cloud);  // 16 points of 0 beside 1
  size_t moved = 0;
  EXPECT_EQ(Rejoined(cloud, &moved), cloud.cluster_of);
  EXPECT_EQ(moved, 0u);
}

}  // namespace
}  // namespace avc::cluster
