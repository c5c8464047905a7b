#pragma once

// The merge-and-cluster stage of a scan, on files: a model folder's points.ply, ppr.bt and
// build.json (what the build stage wrote) into clusters.ply (for people and viewers) and
// clusters.lcm (the clusters_t message, exactly what the surface stage reads). `avc scan` has it
// run by avc-clusterer over the bus; `avc replay` and the tests run it here.

#include <filesystem>

#include "core/messages/clusters_message.h"
#include "core/stage/stage_server.h"
#include "services/clusterer/merge_and_cluster.h"

namespace avc::clusterer {

// Throws std::runtime_error naming the file or the reason the points could not be clustered.
messages::ClustersContent ClusterModel(const std::filesystem::path& model_dir,
                                       const std::filesystem::path& output_dir,
                                       const ClustererOptions& options);

// clusters.lcm as written by ClusterModel. Throws std::runtime_error naming the file.
messages::ClustersContent ReadClustersMessage(const std::filesystem::path& file);

// ClusterModel on a stage job's folders, with `options` changed by the job's settings
// (clusterer_options.h).
stage::StageHandler ClusterStageHandler(const ClustererOptions& options);

}  // namespace avc::clusterer
