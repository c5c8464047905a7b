#pragma once

// The clusterer on a reconstruction folder's files (what `avc reconstruct`, the builder node or a
// scan wrote): points.ply merged into ppr.bt's voxels and clustered. `avc cluster` and a resumed
// scan start here; the same files give the same clusters as the run that wrote them.

#include <filesystem>
#include <string>

#include "services/clusterer/merge_and_cluster.h"

namespace avc::clusterer {

struct FolderInputs {
  std::filesystem::path points_file;  // MVS points PLY
  std::filesystem::path proxy_file;   // the plant proxy .bt
  size_t points = 0;                  // MVS points read
  size_t occupied_voxels = 0;
  double voxel_size = 0;  // metres: build.json's exact value beside the proxy, else the tree's
  std::string note;       // why the tree's rounded voxel size was used, when it was
};

// Throws std::runtime_error naming the file when an input cannot be read or parsed; data
// problems (too few points, a mismatch) come back in the content's `problem`, as from
// MergeAndCluster. `inputs` (optional) receives what was read.
messages::ClustersContent ClusterFolderFiles(const std::filesystem::path& points_file,
                                             const std::filesystem::path& proxy_file,
                                             const ClustererOptions& options,
                                             FolderInputs* inputs = nullptr);

}  // namespace avc::clusterer
