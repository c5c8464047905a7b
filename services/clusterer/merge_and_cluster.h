#pragma once

// The clusterer's work (paper §3), the same offline (`avc cluster`, `avc reconstruct`) and on the
// bus (clusterer_node.h): MVS points merged into the plant proxy's voxels (one averaged point
// per voxel holding more than 3), then the merged points clustered by Algorithm 2 into surface
// patches.

#include <string>

#include "core/cluster/cluster_plant.h"
#include "core/merge/merge_points.h"
#include "core/messages/clusters_message.h"
#include "core/mvs/mvs_bounds.h"
#include "core/mvs/mvs_points.h"

namespace avc::clusterer {

struct ClustererOptions {
  merge::MergeOptions merge;
  cluster::ClusterOptions cluster;

  // Empty when usable; else a sentence naming the bad setting.
  std::string Validate() const;
};

// Never throws for bad data: empty or inconsistent points (NaN, missing normals), an empty proxy,
// a grid mismatch or too few merged points to cluster leave `problem` saying what and where,
// with whatever was merged (all points kUnassigned when clustering could not run).
messages::ClustersContent MergeAndCluster(const mvs::MvsPoints& points, const mvs::MvsBounds& proxy,
                                          const ClustererOptions& options,
                                          const std::string& cloud_id, const std::string& map_id);

// Clusters points already merged (`avc reconstruct` merges in the builder). Same contract.
messages::ClustersContent ClusterMerged(merge::MergedPoints merged, int64_t raw_points,
                                        const cluster::ClusterOptions& options,
                                        const std::string& cloud_id, const std::string& map_id);

}  // namespace avc::clusterer
