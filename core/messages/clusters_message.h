#pragma once

// Clusters on the bus: the clusterer's merged, clustered points <-> clusters_t
// (lcmtypes/avc/clusters_t.lcm). Records: x y z nx ny nz confidence (float32), red green blue
// (uint8), cluster, voxel_x voxel_y voxel_z, merged_from (int32), little-endian.

#include <avc/clusters_t.hpp>
#include <cstdint>
#include <string>

#include "core/cluster/point_set.h"
#include "core/merge/merge_points.h"

namespace avc::messages {

struct ClustersContent {
  std::string cloud_id;  // the MVS points this answers
  std::string map_id;    // the proxy they were merged into
  std::string problem;   // empty: merged and clustered; else why not (merged may be empty)
  merge::MergedPoints merged;
  cluster::Assignment clusters;  // per merged point: 0..num_clusters-1 or kUnassigned
  int32_t num_clusters = 0;
  int64_t raw_points = 0;
};

// Throws std::invalid_argument naming the cloud when the merged points are inconsistent (counts
// of confidences, voxels, clusters), a cluster id is out of range, or a voxel count exceeds int32.
avc::clusters_t ClustersToMessage(const ClustersContent& content);

// Reads fields by name. Throws std::invalid_argument naming the cloud and the field or point at
// fault (sizes, missing fields, cluster ids outside -1..num_clusters-1, non-finite values).
ClustersContent ClustersFromMessage(const avc::clusters_t& message);

}  // namespace avc::messages
