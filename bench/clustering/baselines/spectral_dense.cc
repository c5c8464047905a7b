#include "bench/clustering/baselines/spectral_dense.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "bench/clustering/baselines/input_checks.h"
#include "bench/clustering/baselines/spectral_embedding.h"

namespace avc::cluster::baselines {

Assignment DenseSpectralClustering(const PointSet& set, const DenseSpectralOptions& options) {
  CheckPoints(set, "dense spectral");
  CheckClusterCount(options.clusters, set.points.size(), "dense spectral");
  if (options.sigma_neighbour < 1) {
    throw std::invalid_argument("dense spectral: sigma_neighbour must be >= 1");
  }
  const Eigen::Index n = static_cast<Eigen::Index>(set.points.size());
  Eigen::MatrixXd squared(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) {
      squared(i, j) = (set.points[static_cast<size_t>(i)] - set.points[static_cast<size_t>(j)])
                          .cast<double>()
                          .squaredNorm();
    }
  }
  const Eigen::Index k = std::min<Eigen::Index>(options.sigma_neighbour, n - 1);
  std::vector<double> kth(static_cast<size_t>(n), 0.0);
  if (k > 0) {
    std::vector<double> row(static_cast<size_t>(n));
    for (Eigen::Index i = 0; i < n; ++i) {
      std::copy(squared.col(i).data(), squared.col(i).data() + n, row.begin());
      std::nth_element(row.begin(), row.begin() + k, row.end());  // row[0] is the point itself
      kth[static_cast<size_t>(i)] = std::sqrt(row[static_cast<size_t>(k)]);
    }
  }
  const double sigma = MedianDistance(std::move(kth));
  Eigen::MatrixXd& affinity = squared;  // reused in place: n^2 doubles is the big allocation
  affinity = (-affinity / (2 * sigma * sigma)).array().exp();
  affinity.diagonal().setZero();
  Eigen::VectorXd inv_sqrt_degree = affinity.rowwise().sum();
  for (Eigen::Index i = 0; i < n; ++i) {
    inv_sqrt_degree[i] = inv_sqrt_degree[i] > 0 ? 1.0 / std::sqrt(inv_sqrt_degree[i]) : 0.0;
  }
  affinity = inv_sqrt_degree.asDiagonal() * affinity * inv_sqrt_degree.asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(affinity);
  if (solver.info() != Eigen::Success) {
    throw std::runtime_error("dense spectral: eigendecomposition did not converge");
  }
  // Eigenvalues ascend: the top K eigenvectors are the last K columns.
  return ClusterEmbedding(solver.eigenvectors().rightCols(options.clusters), options.clusters,
                          options.restarts, options.seed);
}

}  // namespace avc::cluster::baselines
