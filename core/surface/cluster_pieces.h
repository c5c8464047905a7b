#pragma once

// The pieces of one cluster that are joined on one surface (chains of neighbours closer than
// the link radius whose offset stays near both tangent planes, cluster/connected_components.h).
// Each piece is triangulated as its own cell: two leaves stacked inside one cluster would
// otherwise be triangulated across on the regression plane.

#include <cstdint>
#include <vector>

#include "core/surface/clustered_points.h"

namespace avc::surface {

// members: the cluster's point indices (ascending). Pieces are sorted ascending and ordered by
// their smallest index. allowance: noise allowance (m) of the tangent-plane test, used only
// when the input has normals.
std::vector<std::vector<uint32_t>> SplitIntoPieces(const ClusteredPoints& input,
                                                   const std::vector<uint32_t>& members,
                                                   double link_radius, double allowance);

}  // namespace avc::surface
