#pragma once

// MVS points on disk: a PLY point cloud (x y z, nx ny nz, red green blue) with two more vertex
// properties, `float confidence` and `list uchar int view_indices`, which every PLY viewer skips.
// The view indices refer to the dataset's image order (the scan's cameras.json).

#include <filesystem>
#include <string>

#include "core/mvs/mvs_points.h"

namespace avc::mvs {

// Same points → same bytes. Throws std::runtime_error naming the file, or std::invalid_argument
// when the points are inconsistent (MvsPoints::Validate) or a point has more than 255 views.
std::string MvsPointsToPly(const MvsPoints& points, bool binary = true);
void WriteMvsPointsPly(const std::filesystem::path& path, const MvsPoints& points,
                       bool binary = true);

// Reads what WriteMvsPointsPly wrote; a plain PLY cloud reads too (confidence 1, no views,
// normals and colours zero when absent). Errors name the file and the vertex at fault.
MvsPoints ReadMvsPointsPly(const std::filesystem::path& path);

}  // namespace avc::mvs
