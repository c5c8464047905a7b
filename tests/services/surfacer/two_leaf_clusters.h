#pragma once

// A tiny clustered plant for the surfacer tests: two horizontal discs (leaves) of 3 cm radius,
// 4 cm apart, each its own cluster, sampled evenly as merged points are (Vogel's spiral), green,
// with the voxel indices and counts the clusterer's product carries.

#include <cmath>
#include <numbers>

#include "core/messages/clusters_message.h"
#include "tests/core/surface/surface_test_points.h"

namespace avc::surfacer::testing {

inline constexpr double kLeafRadius = 0.03;
inline constexpr double kVoxel = 0.002;

inline messages::ClustersContent TwoLeafClusters(const std::string& cloud_id, int per_leaf = 500) {
  messages::ClustersContent content;
  content.cloud_id = cloud_id;
  content.map_id = "plant-ppr-0001";
  content.num_clusters = 2;
  merge::MergedPoints& merged = content.merged;
  merged.voxel_size = kVoxel;
  for (int leaf = 0; leaf < 2; ++leaf) {
    const surface::ClusteredPoints disc = surface::test::SpiralDisc(kLeafRadius, per_leaf);
    for (size_t i = 0; i < disc.cloud.size(); ++i) {
      const Eigen::Vector3f p =
          disc.cloud.positions[i] + Eigen::Vector3f(0, 0, 0.05f + 0.04f * leaf);
      merged.cloud.positions.push_back(p);
      merged.cloud.normals.push_back(disc.cloud.normals[i]);
      merged.cloud.colors.emplace_back(40, 150 + 50 * leaf, 40);
      merged.confidence.push_back(0.9f);
      merged.point_counts.push_back(5);
      merged.voxels.push_back((p / static_cast<float>(kVoxel)).array().floor().cast<int>());
      content.clusters.push_back(leaf);
    }
  }
  content.raw_points = 5 * static_cast<int64_t>(merged.size());
  return content;
}

inline double TwoLeafArea() { return 2.0 * std::numbers::pi * kLeafRadius * kLeafRadius; }

}  // namespace avc::surfacer::testing
