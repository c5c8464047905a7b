#pragma once

// Keeps the faces of a mesh that lie near the data it was reconstructed from (for the
// approximating baselines, whose surfaces run on where there were no points).

#include <Eigen/Core>
#include <vector>

#include "core/geometry/mesh.h"

namespace avc::surface::baselines {

// Removes faces whose centroid has no point within max_distance, then the unused vertices.
// Returns how many faces were removed.
size_t TrimToData(geometry::Mesh& mesh, const std::vector<Eigen::Vector3f>& points,
                  double max_distance);

}  // namespace avc::surface::baselines
