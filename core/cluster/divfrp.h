#pragma once

// The separation constraint's split (paper §3.2 Step 2): a modified DIVFRP (Zhong et al., Pattern
// Recognition Letters 29, 2008). DIVFRP orders a cluster by distance to its furthest reference
// point (the point furthest from the centroid) and cuts the 1-D order where the dissimilarity of
// the two parts is largest. Modified here: the dissimilarity of a cut is the gap between
// consecutive reference distances, a cut is only accepted when that gap exceeds the link radius
// (distinct groups at the point-spacing scale; so the number of clusters is automatic), and groups
// the 1-D order cannot separate (gaps hidden by the projection) are split along the connected
// components instead, peeling off the component that holds the reference point.

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/cluster/neighbour_lists.h"

namespace avc::cluster {

// Two non-empty groups (each sorted ascending), or an empty vector when the cluster is one group.
// neighbours: the same-surface neighbours within link_radius (m) of every point.
std::vector<std::vector<uint32_t>> SplitByFurthestReference(
    const NeighbourLists& neighbours, const std::vector<Eigen::Vector3f>& points,
    const std::vector<uint32_t>& cluster, float link_radius, std::vector<int32_t>* scratch);

}  // namespace avc::cluster
