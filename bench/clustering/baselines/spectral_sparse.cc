#include "bench/clustering/baselines/spectral_sparse.h"

#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "bench/clustering/baselines/input_checks.h"
#include "bench/clustering/baselines/knn_graph.h"
#include "bench/clustering/baselines/spectral_embedding.h"

namespace avc::cluster::baselines {

Assignment SparseSpectralClustering(const PointSet& set, const SparseSpectralOptions& options) {
  CheckPoints(set, "sparse spectral");
  CheckClusterCount(options.clusters, set.points.size(), "sparse spectral");
  if (options.neighbours < 1 || options.lanczos.max_restarts < 1 ||
      !(options.lanczos.tolerance > 0)) {
    throw std::invalid_argument(
        "sparse spectral: neighbours, Lanczos max_restarts and tolerance must be positive");
  }
  const Eigen::Index n = static_cast<Eigen::Index>(set.points.size());
  if (options.clusters == n) {
    // Every point its own cluster: nothing for Lanczos to find (it needs K < n).
    Assignment all(set.points.size());
    for (size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int32_t>(i);
    return all;
  }
  const KnnGraph graph = BuildKnnGraph(set, options.neighbours);
  std::vector<double> kth;
  for (const std::vector<float>& d : graph.squared_distances) {
    if (!d.empty()) kth.push_back(std::sqrt(static_cast<double>(d.back())));
  }
  const double sigma = MedianDistance(std::move(kth));

  // Symmetric kNN graph: an edge when either point lists the other; both triplets carry the same
  // weight, and setFromTriplets' duplicate-sum is replaced by max so i->j and j->i count once.
  std::vector<Eigen::Triplet<double>> triplets;
  for (size_t i = 0; i < graph.neighbours.size(); ++i) {
    for (size_t j = 0; j < graph.neighbours[i].size(); ++j) {
      const double w =
          std::exp(-static_cast<double>(graph.squared_distances[i][j]) / (2 * sigma * sigma));
      const int32_t other = graph.neighbours[i][j];
      triplets.emplace_back(static_cast<int>(i), other, w);
      triplets.emplace_back(other, static_cast<int>(i), w);
    }
  }
  Eigen::SparseMatrix<double> affinity(n, n);
  affinity.setFromTriplets(triplets.begin(), triplets.end(),
                           [](double a, double b) { return std::max(a, b); });
  Eigen::VectorXd inv_sqrt_degree(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double degree = affinity.col(i).sum();
    inv_sqrt_degree[i] = degree > 0 ? 1.0 / std::sqrt(degree) : 0.0;
  }
  Eigen::SparseMatrix<double> normalised =
      inv_sqrt_degree.asDiagonal() * affinity * inv_sqrt_degree.asDiagonal();

  return ClusterEmbedding(LanczosTopEigenvectors(normalised, options.clusters, options.lanczos),
                          options.clusters, options.restarts, options.seed);
}

}  // namespace avc::cluster::baselines
