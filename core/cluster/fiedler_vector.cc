#include "core/cluster/fiedler_vector.h"

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace avc::cluster {
namespace {

// Eigenvector of the largest eigenvalue of the symmetric tridiagonal matrix with diagonal alpha
// and off-diagonal beta: the eigenvalue alone (QR without vectors), then inverse iteration with a
// shift just above it, solved by the Thomas algorithm (the shifted matrix is definite).
Eigen::VectorXd TopEigenvectorOfTridiagonal(const std::vector<double>& alpha,
                                            const std::vector<double>& beta) {
  const long m = static_cast<long>(alpha.size());
  Eigen::VectorXd diagonal = Eigen::Map<const Eigen::VectorXd>(alpha.data(), m);
  Eigen::VectorXd off(std::max<long>(m - 1, 0));
  for (long k = 0; k + 1 < m; ++k) off[k] = beta[static_cast<size_t>(k)];
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver;
  solver.computeFromTridiagonal(diagonal, off, Eigen::EigenvaluesOnly);
  const double scale = std::max(1.0, solver.eigenvalues().cwiseAbs().maxCoeff());
  const double shift = solver.eigenvalues()[m - 1] + 1e-10 * scale;
  Eigen::VectorXd x = Eigen::VectorXd::Ones(m);
  Eigen::VectorXd c = Eigen::VectorXd::Zero(m);
  Eigen::VectorXd d = Eigen::VectorXd::Zero(m);
  for (int iteration = 0; iteration < 3; ++iteration) {
    // Solve (T - shift I) y = x.
    for (long k = 0; k < m; ++k) {
      const double a = k > 0 ? off[k - 1] : 0.0;
      const double pivot = (diagonal[k] - shift) - (k > 0 ? a * c[k - 1] : 0.0);
      c[k] = k + 1 < m ? off[k] / pivot : 0.0;
      d[k] = (x[k] - (k > 0 ? a * d[k - 1] : 0.0)) / pivot;
    }
    for (long k = m - 2; k >= 0; --k) d[k] -= c[k] * d[k + 1];
    x = d.normalized();
  }
  return x;
}

}  // namespace

std::vector<double> FiedlerVector(const SparseGraph& graph, const std::vector<double>& start,
                                  int lanczos_steps) {
  const size_t n = graph.Vertices();
  if (start.size() != n) {
    throw std::invalid_argument("FiedlerVector: start has " + std::to_string(start.size()) +
                                " values for " + std::to_string(n) + " vertices");
  }
  if (n < 3) return std::vector<double>(n, 0.0);
  Eigen::VectorXd inv_sqrt_degree = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd top =
      Eigen::VectorXd::Zero(n);  // the known top eigenvector of the normalised adjacency
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
  // D^-1/2 W D^-1/2 entries, once: each product is then one multiply-add per edge.
  std::vector<double> normalised(graph.weight.size());
  for (size_t v = 0; v < n; ++v) {
    for (uint32_t e = graph.offset[v]; e < graph.offset[v + 1]; ++e) {
      normalised[e] = graph.weight[e] * inv_sqrt_degree[v] * inv_sqrt_degree[graph.column[e]];
    }
  }
  auto multiply = [&](const Eigen::VectorXd& x, Eigen::VectorXd* y) {
    for (size_t v = 0; v < n; ++v) {
      double sum = 0.0;
      for (uint32_t e = graph.offset[v]; e < graph.offset[v + 1]; ++e) {
        sum += normalised[e] * x[graph.column[e]];
      }
      (*y)[v] = sum;
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
    // Full reorthogonalisation (one classical Gram-Schmidt pass: two matrix-vector products,
    // against the top vector too) keeps the Ritz values clean; a second pass changed no Table 2
    // result.
    w -= top.dot(w) * top;
    const auto done = basis.leftCols(k + 1);
    w -= done * (done.transpose() * w);
    const double norm = w.norm();
    if (k + 1 == steps || norm < 1e-10) break;
    beta.push_back(norm);
    q = w / norm;
  }
  const Eigen::VectorXd ritz =
      basis.leftCols(static_cast<long>(alpha.size())) * TopEigenvectorOfTridiagonal(alpha, beta);
  std::vector<double> fiedler(n);
  // Fix the sign (the first vertex non-positive) so the result does not depend on the solver.
  const double sign = ritz[0] > 0.0 ? -1.0 : 1.0;
  for (size_t v = 0; v < n; ++v)
    fiedler[v] = sign * ritz[static_cast<long>(v)] * inv_sqrt_degree[v];
  return fiedler;
}

}  // namespace avc::cluster
