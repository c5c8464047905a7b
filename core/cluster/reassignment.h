#pragma once

// The outlier / incorrect-patch constraint (paper §3.2 Step 3): points at a cluster's distal edge
// that belong with a neighbouring cluster move there, and spurious tiny groups join the cluster
// they touch.

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/cluster/neighbour_lists.h"
#include "core/cluster/point_grid.h"

namespace avc::cluster {

// cluster_of: one id per point (kUnassigned allowed), updated in place. A point p of cluster a
// moves to a cluster b that has a point within link_radius of p when p fits b's points within
// link_radius better than a's: its normal is better aligned with their regression plane's normal
// and it lies nearer that plane (of several such b, the nearest plane). The planes are local
// because leaves are curved, and p is not required to be nearer b's centroid (the paper's
// "distal" test): on the Table 2 sets both misjudged points where one blade crosses another or
// a thin strip of one leaf lies along the next (whole-cluster planes moved 0.2-1.8 % of the bushy
// sets' points into the wrong blade; the centroid test kept up to 7 points a set in the wrong
// leaf). A part of fewer than 3 points has no plane. Decisions of a round use the state at its
// start (order independent); stops after max_rounds or when no point moved. Returns the number of
// moves.
size_t ReassignDistalPoints(const PointGrid& grid, const std::vector<Eigen::Vector3f>& points,
                            const std::vector<Eigen::Vector3f>& normals, float link_radius,
                            int max_rounds, std::vector<int32_t>* cluster_of);

// Each group of points (a spurious split-off) joins the cluster holding most points within
// link_radius of the group's points; groups touching no cluster stay kUnassigned (outliers).
// Returns the number of points left unassigned.
size_t MergeSpuriousGroups(const PointGrid& grid, const std::vector<Eigen::Vector3f>& points,
                           const std::vector<std::vector<uint32_t>>& groups, float link_radius,
                           std::vector<int32_t>* cluster_of);

// After the moves above, a cluster may hold a few points that its own links no longer reach (a
// strip of a wavy margin left behind by a neck cut, whose neighbours of its cluster have moved).
// Each part of a cluster, other than its largest, smaller than min_points and linked
// (neighbours' link rule) to other clusters' points joins the cluster it has most links to (ties:
// the lower id); decisions use the state at the start. Returns the number of points moved.
size_t RejoinStrandedParts(const NeighbourLists& neighbours, size_t min_points,
                           std::vector<int32_t>* scratch, std::vector<int32_t>* cluster_of);

}  // namespace avc::cluster
