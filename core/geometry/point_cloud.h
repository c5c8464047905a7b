#pragma once

// A point cloud as the system passes it around: MVS output, merged points, evaluation samples.
// Optional per-point attributes are either empty or exactly as long as positions.

#include <fmt/format.h>

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace avc::geometry {

struct PointCloud {
  std::vector<Eigen::Vector3f> positions;  // metres

  // Optional attributes.
  std::vector<Eigen::Vector3f> normals;              // per point: unit normal
  std::vector<Eigen::Matrix<uint8_t, 3, 1>> colors;  // per point: RGB

  size_t size() const { return positions.size(); }
  bool empty() const { return positions.empty(); }

  // Empty when consistent, else a sentence naming the first problem (attribute of the wrong
  // length, non-finite position or normal).
  std::string Validate() const {
    if (!normals.empty() && normals.size() != positions.size()) {
      return fmt::format("normals has {} entries, expected 0 or one per point ({})", normals.size(),
                         positions.size());
    }
    if (!colors.empty() && colors.size() != positions.size()) {
      return fmt::format("colors has {} entries, expected 0 or one per point ({})", colors.size(),
                         positions.size());
    }
    for (size_t i = 0; i < positions.size(); ++i) {
      if (!positions[i].allFinite()) return fmt::format("point {} is not finite", i);
    }
    for (size_t i = 0; i < normals.size(); ++i) {
      if (!normals[i].allFinite()) return fmt::format("normal {} is not finite", i);
    }
    return {};
  }
};

}  // namespace avc::geometry
