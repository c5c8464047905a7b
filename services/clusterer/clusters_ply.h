#pragma once

// clusters.ply: the merged, clustered points as a binary PLY with every clusters_t record field
// as a vertex property (x y z nx ny nz red green blue confidence cluster voxel_x voxel_y voxel_z
// merged_from), so viewers show the points and scripts can colour them by `cluster`.

#include <filesystem>

#include "core/messages/clusters_message.h"

namespace avc::clusterer {

// Same content, same bytes. Throws std::runtime_error naming the file when it cannot be
// written, std::invalid_argument when the content is inconsistent.
void WriteClustersPly(const std::filesystem::path& path, const messages::ClustersContent& content);

}  // namespace avc::clusterer
