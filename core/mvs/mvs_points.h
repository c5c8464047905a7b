#pragma once

// The output of multi-view stereo: oriented, coloured points, each with a confidence and the
// images that see it (the paper's PMVS output, which merging, clustering and the level sets use).

#include <cstdint>
#include <string>
#include <vector>

#include "core/geometry/point_cloud.h"

namespace avc::mvs {

struct MvsPoints {
  // positions (metres), normals (unit, facing the cameras that see the point) and colours
  // (RGB, the mean over the visible images); all three always filled.
  geometry::PointCloud cloud;
  std::vector<float> confidence;             // per point: mean NCC over its visible images, 0..1
  std::vector<std::vector<uint32_t>> views;  // per point: sorted indices of the images that see it

  size_t size() const { return cloud.size(); }
  // Empty when consistent, else a sentence naming the first problem.
  std::string Validate() const;
};

}  // namespace avc::mvs
