#pragma once

// Whether a cluster is a tube about its longest principal axis: a stem or petiole, whose
// normals point away from that axis. The normal constraint (paper §3.2 Step 1) is made for
// leaves: a tube's normals do gain from a split, but only by sorting its points into opposite
// lengthwise strips (a 16 mm wide stem of 116 points fell into four). A leaf arched or curled
// along its length also has normals along its offsets from the axis, but on fewer sides of it
// and at distances that vary: it is still split.

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/cluster/pca.h"

namespace avc::cluster {

// What makes a tube. Looser limits (lower alignment, higher spread) take more arched or curled
// leaves for tubes, which then escape the normal split; stricter ones let stems be split into
// strips. The defaults lie between the stems' and the curled leaves' measured values
// (BENCHMARKS.md, "Where the defaults come from").
struct TubeRule {
  double min_alignment = 0.9;      // median |n . r| (25 degrees)
  double max_radius_spread = 0.3;  // RMS spread of the distances to the axis over their mean
};

// True when the median over the points of |n . r| is at least rule.min_alignment, with r the
// unit offset of the point from the longest axis (through the centroid) and n its unit normal;
// the points with such normals lie all round the axis (6 of 8 sectors); and their distances to
// it vary little (a round cross-section). Points on the axis itself are skipped; false when no
// point is off it.
bool IsTube(const std::vector<Eigen::Vector3f>& points, const std::vector<Eigen::Vector3f>& normals,
            const std::vector<uint32_t>& cluster, const PrincipalAxes& axes, const TubeRule& rule);

}  // namespace avc::cluster
