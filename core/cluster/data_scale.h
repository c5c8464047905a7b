#pragma once

// The scales every clustering threshold is derived from, measured on the data itself.

#include <Eigen/Core>
#include <vector>

namespace avc::cluster {

struct DataScale {
  // Median distance from a point to its nearest neighbour (m): the sampling density.
  double spacing = 0;
  // Median RMS residual of local plane fits over neighbourhoods of radius 2.5 * spacing (m):
  // measurement noise plus the curvature the surface shows at that scale.
  double noise = 0;
};

// Throws std::invalid_argument when fewer than 3 points or all points coincide.
DataScale EstimateDataScale(const std::vector<Eigen::Vector3f>& points);

}  // namespace avc::cluster
