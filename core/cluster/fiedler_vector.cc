#include "core/cluster/fiedler_vector.h"

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace avc::cluster {

std::vector<double> FiedlerVector(const SparseGraph& graph, const std::vector<double>& start,
                                  int lanczos_steps) {
  const size_t n = graph.Vertices();
  if (start.size() != n) {
    throw std::invalid_argument("FiedlerVector: start has " + std::to_string(start.size()) +
                                " values for " + std::to_string(n) + " vertices");
  }
  if (n < 3) return std::vector<double>(n, 0.0);
  Eigen::VectorXd inv_sqrt_degree(n);
  Eigen::VectorXd top(n);  // the known top eigenvector of the normalised adjacency
  for (size_t v = 0; v < n; ++v) {
    double degree = 0.0;
    for (uint32_t e = graph.offset[v]; e < graph.offset[v + 1]; ++e) degree += graph.weight[e];
    if (!(degree > 0.0)) {
      throw std::invalid_argument("FiedlerVector: vertex " + std::to_string(v) + " is isolated");
    }
    inv_sqrt_degree[v] = 1.0 / std::sqrt(degree);
    top[v] = std::sqrt(degree);
  }
  top.normalize();
  auto multiply = [&](const Eigen::VectorXd& x, Eigen::VectorXd* y) {
    for (size_t v = 0; v < n; ++v) {
      double sum = 0.0;
      for (uint32_t e = graph.offset[v]; e < graph.offset[v + 1]; ++e) {
        sum += graph.weight[e] * inv_sqrt_degree[graph.column[e]] * x[graph.column[e]];
      }
      (*y)[v] = inv_sqrt_degree[v] * sum;
    }
  };

  const int steps = std::clamp(lanczos_steps, 2, static_cast<int>(n) - 1);
  Eigen::MatrixXd basis(n, steps);
  std::vector<double> alpha;
  std::vector<double> beta;
  Eigen::VectorXd q = Eigen::Map<const Eigen::VectorXd>(start.data(), static_cast<long>(n));
  q -= top.dot(q) * top;
  if (!(q.norm() > 1e-12)) throw std::invalid_argument("FiedlerVector: start is constant");
  q.normalize();
  Eigen::VectorXd w(n);
  for (int k = 0; k < steps; ++k) {
    basis.col(k) = q;
    multiply(q, &w);
    alpha.push_back(q.dot(w));
    // Full reorthogonalisation (one Gram-Schmidt pass, against the top vector too) keeps the
    // Ritz values clean; a second pass changed no Table 2 result.
    w -= top.dot(w) * top;
    for (int j = 0; j <= k; ++j) w -= basis.col(j).dot(w) * basis.col(j);
    const double norm = w.norm();
    if (k + 1 == steps || norm < 1e-10) break;
    beta.push_back(norm);
    q = w / norm;
  }
  const int m = static_cast<int>(alpha.size());
  Eigen::MatrixXd tridiagonal = Eigen::MatrixXd::Zero(m, m);
  for (int k = 0; k < m; ++k) {
    tridiagonal(k, k) = alpha[static_cast<size_t>(k)];
    if (k + 1 < m) {
      tridiagonal(k, k + 1) = tridiagonal(k + 1, k) = beta[static_cast<size_t>(k)];
    }
  }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(tridiagonal);
  const Eigen::VectorXd ritz = basis.leftCols(m) * solver.eigenvectors().col(m - 1);
  std::vector<double> fiedler(n);
  // Fix the sign (the first vertex non-positive) so the result does not depend on the solver.
  const double sign = ritz[0] > 0.0 ? -1.0 : 1.0;
  for (size_t v = 0; v < n; ++v)
    fiedler[v] = sign * ritz[static_cast<long>(v)] * inv_sqrt_degree[v];
  return fiedler;
}

}  // namespace avc::cluster
