// Model merging on a hand-made proxy and cloud whose voxels and averages are known.

#include "core/merge/merge_points.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace avc::merge {
namespace {

constexpr double kVoxel = 0.01;

Eigen::Vector3f Centre(int x, int y, int z) {
  return (kVoxel * (Eigen::Vector3d(x, y, z).array() + 0.5)).matrix().cast<float>();
}

void AddPoint(mvs::MvsPoints& points, const Eigen::Vector3f& position,
              const Eigen::Vector3f& normal, uint8_t grey, float confidence) {
  points.cloud.positions.push_back(position);
  points.cloud.normals.push_back(normal.normalized());
  points.cloud.colors.push_back({grey, grey, grey});
  points.confidence.push_back(confidence);
  points.views.push_back({0, 1, 2});
}

TEST(MergeIntoProxy, AveragesDenseVoxelsAndCountsWhatItDrops) {
  mvs::MvsBounds proxy{{Centre(0, 0, 0), Centre(1, 0, 0), Centre(0, 0, 1)}, kVoxel};
  mvs::MvsPoints points;
  // Voxel (1, 0, 0): five points around (15, 5, 5) mm.
  for (int k = 0; k < 5; ++k) {
    AddPoint(points, Centre(1, 0, 0) + Eigen::Vector3f(0.001f * (k - 2), 0, 0),
             {0, 0.1f * (k - 2), 1}, static_cast<uint8_t>(100 + 10 * k), 0.5f + 0.1f * k);
  }
  // Voxel (0, 0, 0): four points, the minimum kept.
  for (int k = 0; k < 4; ++k) AddPoint(points, Centre(0, 0, 0), {1, 0, 0}, 50, 1.0f);
  // Voxel (0, 0, 1): three points, too few.
  for (int k = 0; k < 3; ++k) AddPoint(points, Centre(0, 0, 1), {1, 0, 0}, 50, 1.0f);
  // Two points in voxels the proxy does not occupy.
  AddPoint(points, Centre(5, 5, 5), {1, 0, 0}, 0, 1.0f);
  AddPoint(points, Centre(-1, 0, 0), {1, 0, 0}, 0, 1.0f);

  const MergedPoints merged = MergeIntoProxy(points, proxy);
  ASSERT_EQ(merged.size(), 2u);
  EXPECT_EQ(merged.outside_proxy, 2u);
  EXPECT_EQ(merged.in_sparse_voxels, 3u);
  // Sorted by (z, y, x): voxel (0, 0, 0) first.
  EXPECT_EQ(merged.voxels[0], Eigen::Vector3i(0, 0, 0));
  EXPECT_EQ(merged.voxels[1], Eigen::Vector3i(1, 0, 0));
  EXPECT_EQ(merged.point_counts, (std::vector<uint32_t>{4, 5}));
  EXPECT_LT((merged.cloud.positions[1] - Centre(1, 0, 0)).norm(), 1e-6f);
  EXPECT_LT((merged.cloud.normals[1] - Eigen::Vector3f(0, 0, 1)).norm(), 1e-6f);
  EXPECT_EQ(merged.cloud.colors[1], (Eigen::Matrix<uint8_t, 3, 1>(120, 120, 120)));
  EXPECT_NEAR(merged.confidence[1], 0.7f, 1e-6f);
  EXPECT_EQ(merged.voxel_size, kVoxel);
}

TEST(PointsInProxy, KeepsThePointsInOrNearOccupiedVoxelsInTheirOrder) {
  const mvs::MvsBounds proxy{{Centre(0, 0, 0), Centre(1, 0, 0)}, kVoxel};
  mvs::MvsPoints points;
  AddPoint(points, Centre(1, 0, 0), {0, 0, 1}, 10, 0.1f);   // in
  AddPoint(points, Centre(2, 1, 0), {0, 0, 1}, 20, 0.2f);   // a voxel off (diagonal)
  AddPoint(points, Centre(0, 0, 0), {0, 0, 1}, 30, 0.3f);   // in
  AddPoint(points, Centre(-3, 0, 0), {0, 0, 1}, 40, 0.4f);  // three voxels off
  uint64_t removed = 0;
  const mvs::MvsPoints in = PointsInProxy(points, proxy, 0, &removed);
  EXPECT_EQ(removed, 2u);
  ASSERT_EQ(in.size(), 2u);
  EXPECT_TRUE(in.Validate().empty());
  EXPECT_EQ(in.cloud.colors[0][0], 10);
  EXPECT_EQ(in.cloud.colors[1][0], 30);
  EXPECT_EQ(in.confidence[1], 0.3f);
  const mvs::MvsPoints near = PointsInProxy(points, proxy, 1, &removed);
  EXPECT_EQ(removed, 1u);
  ASSERT_EQ(near.size(), 3u);
  EXPECT_EQ(near.cloud.colors[1][0], 20);
  EXPECT_EQ(PointsInProxy(points, proxy, 3).size(), 4u);
  EXPECT_THROW(PointsInProxy(points, proxy, -1), std::invalid_argument);
  EXPECT_THROW(PointsInProxy(points, {{Centre(0, 0, 0)}, 0.0}, 0), std::invalid_argument);
}

TEST(MergeIntoProxy, AHigherMinimumKeepsFewerVoxels) {
  mvs::MvsBounds proxy{{Centre(0, 0, 0)}, kVoxel};
  mvs::MvsPoints points;
  for (int k = 0; k < 4; ++k) AddPoint(points, Centre(0, 0, 0), {1, 0, 0}, 50, 1.0f);
  EXPECT_EQ(MergeIntoProxy(points, proxy, {.min_points = 4}).size(), 1u);
  const MergedPoints none = MergeIntoProxy(points, proxy, {.min_points = 5});
  EXPECT_EQ(none.size(), 0u);
  EXPECT_EQ(none.in_sparse_voxels, 4u);
}

TEST(MergeIntoProxy, RefusesBadInputNamingIt) {
  mvs::MvsPoints points;
  AddPoint(points, Centre(0, 0, 0), {1, 0, 0}, 50, 1.0f);
  auto message = [&](const mvs::MvsPoints& p, const mvs::MvsBounds& b, int min_points) {
    try {
      MergeIntoProxy(p, b, {.min_points = min_points});
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message(points, {{Centre(0, 0, 0)}, 0}, 4).find("voxel size"), std::string::npos);
  EXPECT_NE(message(points, {{Eigen::Vector3f(0.001f, 0.005f, 0.005f)}, kVoxel}, 4)
                .find("not a voxel centre"),
            std::string::npos);
  EXPECT_NE(message(points, {{Centre(0, 0, 0)}, kVoxel}, 0).find("min_points"), std::string::npos);
  mvs::MvsPoints broken = points;
  broken.confidence.clear();
  EXPECT_FALSE(message(broken, {{Centre(0, 0, 0)}, kVoxel}, 4).empty());
}

}  // namespace
}  // namespace avc::merge
