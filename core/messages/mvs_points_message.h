#pragma once

// MVS points on the bus: MvsPoints <-> mvs_points_t (lcmtypes/avc/mvs_points_t.lcm). Points are
// point_cloud_t records with fields x y z nx ny nz (float32), red green blue (uint8) and
// confidence (float32), little-endian; each point's view indices refer to image_ids and travel
// as a uint8 count followed by that many little-endian uint16 indices.

#include <avc/mvs_points_t.hpp>
#include <string>
#include <vector>

#include "core/mvs/mvs_points.h"

namespace avc::messages {

struct MvsPointsMessageContent {
  mvs::MvsPoints points;
  std::vector<std::string> image_ids;  // what points.views index
};

// Throws std::invalid_argument when the points are inconsistent (MvsPoints::Validate), a point
// has more than 255 views, or a view index is not below image_ids.size() (at most 65536 images).
avc::mvs_points_t MvsPointsToMessage(const mvs::MvsPoints& points,
                                     const std::vector<std::string>& image_ids,
                                     const std::string& cloud_id);

// Reads fields by name, so any record layout with those fields reads (colours may also be named
// r g b). Throws std::invalid_argument naming the cloud and the field or point at fault.
MvsPointsMessageContent MvsPointsFromMessage(const avc::mvs_points_t& message);

}  // namespace avc::messages
