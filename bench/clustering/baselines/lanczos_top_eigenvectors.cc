#include "bench/clustering/baselines/lanczos_top_eigenvectors.h"

#include <Spectra/SymEigsSolver.h>
#include <fmt/format.h>

#include <algorithm>
#include <random>
#include <stdexcept>
#include <vector>

namespace avc::cluster::baselines {
namespace {

struct EigenPair {
  double value;
  Eigen::VectorXd vector;
};

// y = (A - sum_i (lambda_i + shift) v_i v_i^T) x: found pairs move to lambda = -shift, below the
// spectrum, so Lanczos finds the next largest eigenvalues (including further copies of a
// repeated one).
class DeflatedProduct {
 public:
  using Scalar = double;
  DeflatedProduct(const Eigen::SparseMatrix<double>& matrix, const std::vector<EigenPair>& found,
                  double shift)
      : matrix_(matrix),
        basis_(matrix.rows(), static_cast<Eigen::Index>(found.size())),
        weights_(static_cast<Eigen::Index>(found.size())) {
    for (size_t i = 0; i < found.size(); ++i) {
      basis_.col(static_cast<Eigen::Index>(i)) = found[i].vector;
      weights_[static_cast<Eigen::Index>(i)] = found[i].value + shift;
    }
  }
  Eigen::Index rows() const { return matrix_.rows(); }
  Eigen::Index cols() const { return matrix_.cols(); }
  void perform_op(const double* x_in, double* y_out) const {
    const Eigen::Map<const Eigen::VectorXd> x(x_in, matrix_.cols());
    Eigen::Map<Eigen::VectorXd> y(y_out, matrix_.rows());
    y.noalias() = matrix_ * x;
    if (basis_.cols() > 0) {
      y.noalias() -= basis_ * weights_.asDiagonal() * (basis_.transpose() * x);
    }
  }

 private:
  const Eigen::SparseMatrix<double>& matrix_;
  Eigen::MatrixXd basis_;
  Eigen::VectorXd weights_;
};

std::vector<EigenPair> RunLanczos(const Eigen::SparseMatrix<double>& matrix,
                                  const std::vector<EigenPair>& found, double shift, int wanted,
                                  uint64_t start_seed, const LanczosOptions& options) {
  const Eigen::Index n = matrix.rows();
  const Eigen::Index krylov = std::min<Eigen::Index>(
      n, options.krylov_vectors > 0 ? options.krylov_vectors : std::max(2 * wanted + 1, 20));
  if (krylov <= wanted) {
    throw std::invalid_argument(fmt::format(
        "Lanczos: {} Krylov vectors for {} eigenpairs of a {}x{} matrix", krylov, wanted, n, n));
  }
  DeflatedProduct product(matrix, found, shift);
  Spectra::SymEigsSolver<DeflatedProduct> solver(product, wanted, krylov);
  // A fresh seeded start vector per run: one shared by every run would have no component left in
  // the rest of a repeated eigenspace once its first copy is deflated.
  std::mt19937_64 rng(start_seed);
  Eigen::VectorXd start(n);
  for (Eigen::Index i = 0; i < n; ++i)
    start[i] = static_cast<double>(rng() >> 11) * 0x1.0p-53 - 0.5;
  solver.init(start.data());
  solver.compute(Spectra::SortRule::LargestAlge, options.max_restarts, options.tolerance);
  if (solver.info() != Spectra::CompInfo::Successful) {
    throw std::runtime_error(
        fmt::format("Lanczos did not converge: {} eigenpairs of a {}x{} matrix in {} restarts",
                    wanted, n, n, options.max_restarts));
  }
  std::vector<EigenPair> pairs;
  for (int i = 0; i < wanted; ++i) {
    pairs.push_back({solver.eigenvalues()[i], solver.eigenvectors().col(i)});
  }
  return pairs;
}

}  // namespace

Eigen::MatrixXd LanczosTopEigenvectors(const Eigen::SparseMatrix<double>& symmetric, int count,
                                       const LanczosOptions& options) {
  const Eigen::Index n = symmetric.rows();
  if (symmetric.cols() != n || count < 1 || count >= n) {
    throw std::invalid_argument(fmt::format(
        "Lanczos: {} eigenpairs of a {}x{} matrix (need a square matrix and 1 <= count < n)", count,
        n, symmetric.cols()));
  }
  // |lambda| <= the largest absolute row sum, so this shift puts deflated pairs below all others.
  double bound = 0;
  for (Eigen::Index c = 0; c < n; ++c) bound = std::max(bound, symmetric.col(c).cwiseAbs().sum());
  const double shift = 2 * bound + 1;
  const double resolution = 1e3 * options.tolerance * std::max(bound, 1.0);

  std::vector<EigenPair> found = RunLanczos(symmetric, {}, shift, count, 0, options);
  // Each check either confirms the set or swaps in a missed larger eigenvalue (a repeated copy);
  // at most count swaps can be needed for a count-fold eigenvalue.
  for (int check = 0; check <= count; ++check) {
    auto smallest = std::min_element(
        found.begin(), found.end(), [](const auto& a, const auto& b) { return a.value < b.value; });
    EigenPair next =
        RunLanczos(symmetric, found, shift, 1, static_cast<uint64_t>(check) + 1, options).front();
    if (next.value <= smallest->value + resolution) {
      std::stable_sort(found.begin(), found.end(),
                       [](const auto& a, const auto& b) { return a.value > b.value; });
      Eigen::MatrixXd vectors(n, count);
      for (int i = 0; i < count; ++i) vectors.col(i) = found[static_cast<size_t>(i)].vector;
      return vectors;
    }
    *smallest = std::move(next);
  }
  throw std::runtime_error(fmt::format(
      "Lanczos: the top {} eigenpairs did not settle after {} deflation checks", count, count + 1));
}

}  // namespace avc::cluster::baselines
