#pragma once

// The spectral bipartition shared by the neck and overlapping-sheet splits: a cluster's
// k-nearest same-surface neighbour graph, edge weights from how much the normals bend along each
// edge, and the least-conductance sweep cut of the graph's Fiedler order.

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/cluster/fiedler_vector.h"
#include "core/cluster/neighbour_lists.h"

namespace avc::cluster {

using LocalEdge = std::pair<uint32_t, uint32_t>;  // local vertex ids (cluster positions), a < b

struct ClusterGraph {
  std::vector<LocalEdge> edges;  // symmetrised, each once (deterministic order)
  // Per vertex: distance to the furthest of its k neighbours (m; 0 without neighbours).
  std::vector<float> reach;
};

// Each point's k nearest same-surface neighbours that are in the cluster, symmetrised.
// scratch must hold one int per point and all -1; it is restored before returning.
ClusterGraph NeighbourGraph(const NeighbourLists& neighbours,
                            const std::vector<Eigen::Vector3f>& points,
                            const std::vector<uint32_t>& cluster, int k,
                            std::vector<int32_t>* scratch);

// 1 - |n_a . n_b| per edge (about angle^2 / 2; sign-free), normals[vertex] indexed locally.
std::vector<float> EdgeBends(const std::vector<LocalEdge>& edges,
                             const std::vector<Eigen::Vector3f>& local_normals);

// Per edge, the squared sine of its steeper elevation above the two points' tangent planes,
// max(|d . n_a|, |d . n_b|)^2 / |d|^2 with d the offset (0 for coincident points): small between
// neighbours on one sheet (noise, curvature), large between two sheets that touch one above the
// other's edge. points are indexed by cluster[vertex], normals locally.
std::vector<float> EdgeElevations(const std::vector<LocalEdge>& edges,
                                  const std::vector<Eigen::Vector3f>& points,
                                  const std::vector<uint32_t>& cluster,
                                  const std::vector<Eigen::Vector3f>& local_normals);

// exp(-b / (bend_factor * median b)): an edge bent much more than is typical in the cluster is
// weak. The floor 1e-3 keeps every vertex's degree positive. All 1 when bend_factor <= 0 or the
// median bend is 0.
std::vector<float> BendWeights(const std::vector<float>& bends, double bend_factor);

struct SpectralCut {
  std::vector<uint32_t> order;  // local vertices in Fiedler order
  size_t size = 0;              // the first `size` of order are side A; 0: no cut allowed
  double cut = 0;               // weight of the edges crossing the cut
  double total_volume = 0;      // sum of all degrees
};

// The weighted graph in compressed rows (weights[e] on edges[e]).
SparseGraph WeightedGraph(size_t vertices, const std::vector<LocalEdge>& edges,
                          const std::vector<float>& weights);

// Least-conductance prefix of the Fiedler order with both sides at least min_side vertices.
// start seeds the Krylov space (not constant). Returns size 0 when a vertex has no edge (the
// spectrum is degenerate: that is the connected-component split's business).
SpectralCut LeastConductanceCut(const SparseGraph& graph, const std::vector<double>& start,
                                int lanczos_steps, size_t min_side);

// Side per vertex (0 = side A) of a cut.
std::vector<uint8_t> CutSideOfVertex(const SpectralCut& cut);

// Local improvement of a two-sided cut: in up to `rounds` passes over the vertices in order, a
// vertex with more edge weight to the other side than to its own moves there (a few dozen Lanczos
// steps leave the order approximate where the spectrum is nearly degenerate; the moves only lower
// the cut weight). Deterministic.
void RefineCut(const SparseGraph& graph, int rounds, std::vector<uint8_t>* side);

// Weight of the edges between the two sides.
double CutWeight(const SparseGraph& graph, const std::vector<uint8_t>& side);

// The two sides of a cut as sorted point indices (groups[0] = side A).
std::vector<std::vector<uint32_t>> CutSides(const std::vector<uint32_t>& cluster,
                                            const SpectralCut& cut);
std::vector<std::vector<uint32_t>> CutSides(const std::vector<uint32_t>& cluster,
                                            const std::vector<uint8_t>& side);

// Positions along the cluster's longest principal axis: the Fiedler vector's first guess for an
// elongated pair.
std::vector<double> LongestAxisStart(const std::vector<Eigen::Vector3f>& points,
                                     const std::vector<uint32_t>& cluster);

}  // namespace avc::cluster
