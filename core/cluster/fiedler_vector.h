#pragma once

// The Fiedler vector of a weighted undirected graph: the eigenvector of the second-smallest
// eigenvalue of the normalised Laplacian I - D^-1/2 W D^-1/2 (spectral bipartitioning, Shi and
// Malik's normalised cut). Computed by Lanczos with full reorthogonalisation on the normalised
// adjacency, deflated against its known top eigenvector sqrt(degree): a few dozen sparse products,
// no dense matrix, deterministic (fixed start vector, fixed order).

#include <cstddef>
#include <cstdint>
#include <vector>

namespace avc::cluster {

// Symmetric sparse graph in compressed rows: the neighbours of vertex v are
// column[offset[v]] .. column[offset[v + 1] - 1] with the matching weights (> 0).
struct SparseGraph {
  std::vector<uint32_t> offset;  // vertices + 1 entries
  std::vector<uint32_t> column;
  std::vector<float> weight;

  size_t Vertices() const { return offset.empty() ? 0 : offset.size() - 1; }
};

// One value per vertex (D^-1/2 times the eigenvector, so thresholding it is the spectral cut).
// start seeds the Krylov space (e.g. positions along the longest axis; must not be constant).
// Throws std::invalid_argument for a graph with an isolated vertex or a start of the wrong size.
std::vector<double> FiedlerVector(const SparseGraph& graph, const std::vector<double>& start,
                                  int lanczos_steps);

}  // namespace avc::cluster
