#pragma once

// Separation at a narrow neck (Algorithm 2 Step 2, the separation constraint, for groups that
// touch): two leaves that touch along a short contact are one connected component at the link
// radius, so DIVFRP finds no gap, and when they face almost the same way the normal step gains
// too little to cut them. On the k-nearest-neighbour graph of the cluster (same-surface links,
// edges weakened where the two normals bend much more than is typical between neighbours) the
// spectral (Fiedler) order is swept for the cut of least conductance; the cut is a neck when the
// contact it crosses is short compared with the narrower side's width. A single leaf or a stem
// cut across crosses its full width and is kept whole, however elongated it is.
//
// A kept cut's boundary is then redrawn where the surface, not just the graph, changes: the
// least-conductance cut follows the narrowest band of edges, which can leave a strip of one leaf
// (its wavy margin, a narrow tip lying along the next leaf) with the other leaf. The edges from
// such a strip into the other leaf rise steeply off the tangent planes (sine of the elevation,
// median 0.34-0.55 on the Table 2 sets' strips), those inside a sheet do not (0.09-0.14), so the
// cut is taken again on the graph weighted by elevation too, adopted when it only moves the
// boundary (at most max_boundary_shift of the smaller side changes side), and refined point by
// point.

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/cluster/spectral_cut.h"

namespace avc::cluster {

struct NeckRule {
  int neighbours = 10;     // k of the k-nearest-neighbour graph (within the link radius)
  int lanczos_steps = 40;  // Krylov dimension of the Fiedler vector
  size_t min_side = 13;    // each side holds at least this many points
  // Edge weight exp(-b / (bend_factor * median b)) with b = 1 - |n_i . n_j| ~ angle^2 / 2: an edge
  // bent sqrt(bend_factor) times more than the cluster's median neighbour angle weighs 1/e.
  // 0 = unweighted.
  double bend_factor = 16.0;
  // Split when the contact's length (estimated from the cut weight, the degree and the neighbour
  // reach) is at most this fraction of the narrower side's width (2 sqrt(3 lambda_mid)).
  double max_neck_ratio = 0.5;
  // Boundary redrawing: edge weights also exp(-e / (elevation_factor * median e)), e the squared
  // sine of the edge's elevation (spectral_cut.h, EdgeElevations): an edge rising twice as steeply
  // as the median one weighs 1/e. 0 = keep the least-conductance cut as it is.
  double elevation_factor = 4.0;
  // The redrawn cut is adopted when at most this fraction of the smaller side changes side (else
  // it is another cut, not the same one redrawn).
  double max_boundary_shift = 0.1;
  // Passes of point-wise refinement (spectral_cut.h, RefineCut) of the redrawn boundary.
  int refinement_rounds = 4;
};

struct NeckCut {
  std::vector<std::vector<uint32_t>> groups;  // two sorted groups, or empty: no neck
  double ratio = 0;  // neck ratio of the least-conductance cut (infinity: no cut allowed)
};

// graph: the cluster's neighbour graph (spectral_cut.h, NeighbourGraph with rule.neighbours);
// normals weight the edges (nullptr: unweighted).
NeckCut SplitAtNeck(const ClusterGraph& graph, const std::vector<Eigen::Vector3f>& points,
                    const std::vector<Eigen::Vector3f>* normals,
                    const std::vector<uint32_t>& cluster, const NeckRule& rule);

}  // namespace avc::cluster
