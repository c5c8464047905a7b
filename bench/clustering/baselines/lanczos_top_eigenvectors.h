#pragma once

// The K largest eigenpairs of a sparse symmetric matrix by implicitly restarted Lanczos
// (Spectra), made safe for repeated eigenvalues. A graph with c connected components has the
// top eigenvalue 1 c times over, and plain Lanczos from one start vector sees only one copy of
// it, silently returning smaller eigenvalues instead. So found pairs are deflated (shifted far
// below the spectrum) and Lanczos is asked again until a fresh run finds nothing larger.

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace avc::cluster::baselines {

struct LanczosOptions {
  int krylov_vectors = 0;  // per run; 0: max(2 * wanted + 1, 20), capped at n
  int max_restarts = 1000;
  double tolerance = 1e-10;
};

// n x count eigenvectors, largest eigenvalue first. Requires 1 <= count < n.
// Throws std::runtime_error when Lanczos does not converge.
Eigen::MatrixXd LanczosTopEigenvectors(const Eigen::SparseMatrix<double>& symmetric, int count,
                                       const LanczosOptions& options);

}  // namespace avc::cluster::baselines
