#pragma once

// The normal constraint's split (paper §3.2 Step 1, Fig. 7): project a cluster on its longest
// principal axis, bin the projections into a 1-D array, and cut where the normals on either
// side are each most alike; then let each point join the side whose normals it matches.

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/cluster/pca.h"

namespace avc::cluster {

struct NormalSplit {
  std::vector<uint32_t> left;  // sorted ascending
  std::vector<uint32_t> right;
  // How much more coherent the two sides' normals are than the whole (of the refined split; of
  // the bare cut when that fell below min_gain and the sides are empty), as a fraction of the
  // points: (C(L) + C(R) - C(all)) / n with C the largest eigenvalue of sum(n n^T) (so normal
  // signs do not matter). 0 for a useless cut (a tube cut across, a flat sheet), sin^2(a/2) for
  // two equal planes meeting at angle a, about 0.06 for a sheet bent smoothly through 60 degrees.
  double gain = 0;
};

// axis_index picks the projection axis (a column of axes.axes): 2 = lambda_max, as in the paper.
// Fig. 7 read as: at each bin boundary x, A(x) and B(x) are the summed deviations of the normals
// left and right of x from their side's dominant direction, n_side - C(side); the cut minimises
// A + B (prefix sums of the per-bin tensors, O(n + bins)). A cut whose gain is below min_gain is
// returned with empty sides (PCA cannot improve the cluster). Else refinement_rounds rounds move
// every point to the side whose dominant normal direction it matches better (the cut is a plane
// across the principal axis, the true boundary is not). bin_width > 0 (m). Returns empty sides
// when the cluster spans fewer than 2 bins.
NormalSplit SplitByNormals(const std::vector<Eigen::Vector3f>& points,
                           const std::vector<Eigen::Vector3f>& normals,
                           const std::vector<uint32_t>& cluster, const PrincipalAxes& axes,
                           int axis_index, double bin_width, double min_gain,
                           int refinement_rounds);

}  // namespace avc::cluster
