#pragma once

// Separation of two overlapping sheets (Algorithm 2 Step 2, the separation constraint, for leaves
// that cross): two blades that pass through each other are one connected component (their points
// are within the link radius and on each other's tangent planes near the crossing line), DIVFRP
// finds no gap, the contact is not a narrow neck, and when they differ by 10-30 degrees the normal
// step gains too little to cut them. What does separate them is that the normal field jumps
// where the sheets meet while it varies smoothly inside each sheet, and that each sheet continues
// through the contact.
//
// The cut: the cluster's k-nearest-neighbour graph with edges weighted by the bend of smoothed
// normals (each point's normal averaged with its neighbours' that bend little, so the sampling
// noise does not hide the jump), split at the least-conductance cut of its Fiedler order, refined
// locally (vertices join the side they are more strongly linked to). That cut
// follows a normal discontinuity wherever there is one, also the midrib fold or a crease inside a
// single leaf, so it is kept only when both sides continue through it: at a cut across one sheet
// each side ends there, so a boundary point's own-side neighbours lie away from the other side;
// at a crossing each sheet surrounds the contact line, so they lie all around it.

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/cluster/neighbour_lists.h"
#include "core/cluster/spectral_cut.h"

namespace avc::cluster {

struct SheetRule {
  int lanczos_steps = 60;  // Krylov dimension of the Fiedler vector
  size_t min_side = 13;    // each side, and each side's cut boundary, holds this many points
  // A point's smoothed normal averages its own with those of its graph neighbours whose normals
  // bend at most smoothing_factor times the cluster's median neighbour bend (sampling noise, not a
  // jump between sheets).
  double smoothing_factor = 4.0;
  // Edge weight exp(-b / (bend_factor * median b)) on the smoothed normals.
  double bend_factor = 3.0;
  // Passes of local refinement of the spectral cut (spectral_cut.h, RefineCut).
  int refinement_rounds = 4;
  // Largest edge bias (|median| over a side's boundary points of the own-side neighbours' mean
  // in-plane offset away from the other side, over their mean distance) of a side that continues
  // through the cut. <= 0 disables the split.
  double max_edge_bias = 0.15;
};

struct SheetCut {
  std::vector<std::vector<uint32_t>> groups;  // two sorted groups, or empty: not two sheets
  // The larger of the two sides' edge biases (infinity when no cut was allowed or a side's
  // boundary is too small to tell).
  double edge_bias = 0;
};

// graph: the cluster's k-nearest-neighbour graph (spectral_cut.h, NeighbourGraph); neighbours built
// from points with the link rule; normals unit, one per point. scratch must hold one int per point
// and all -1; it is restored before returning.
SheetCut SplitOverlappingSheets(const ClusterGraph& graph, const NeighbourLists& neighbours,
                                const std::vector<Eigen::Vector3f>& points,
                                const std::vector<Eigen::Vector3f>& normals,
                                const std::vector<uint32_t>& cluster, const SheetRule& rule,
                                std::vector<int32_t>* scratch);

}  // namespace avc::cluster
