#pragma once

// The surfacer's input (paper §4, Algorithm 3): the merged plant points with their normals,
// optional colours and the clusterer's id per point. Points with id cluster::kUnassigned are
// outliers and take no part.

#include <cstdint>
#include <string>
#include <vector>

#include "core/geometry/point_cloud.h"

namespace avc::surface {

struct ClusteredPoints {
  geometry::PointCloud cloud;     // positions (m); normals and colours optional
  std::vector<int32_t> clusters;  // one per point: 0..K-1 or cluster::kUnassigned
};

// The usable points, grouped by cluster id (ascending), each group in ascending point order.
struct ClusterMembers {
  std::vector<int32_t> ids;
  std::vector<std::vector<uint32_t>> points;  // parallel to ids
};

// Throws std::invalid_argument naming the problem when the structure is inconsistent (cluster
// ids or attributes of the wrong length, an id below kUnassigned). Points with a non-finite
// position or normal are left out, with one warning line appended to *warnings.
ClusterMembers GroupByCluster(const ClusteredPoints& input, std::vector<std::string>* warnings);

}  // namespace avc::surface
