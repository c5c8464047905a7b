#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <vector>

#include "bench/clustering/baselines/lanczos_top_eigenvectors.h"

namespace avc::cluster::baselines {
namespace {

// Block-diagonal matrix of `blocks` copies of a weighted path graph's normalised affinity: every
// eigenvalue repeats `blocks` times, the top one (1) included, as for a disconnected kNN graph.
Eigen::SparseMatrix<double> RepeatedBlocks(int blocks, int size) {
  std::vector<Eigen::Triplet<double>> triplets;
  for (int b = 0; b < blocks; ++b) {
    Eigen::MatrixXd w = Eigen::MatrixXd::Zero(size, size);
    for (int i = 0; i + 1 < size; ++i) w(i, i + 1) = w(i + 1, i) = 1.0 + 0.1 * i;
    const Eigen::VectorXd d = w.rowwise().sum().cwiseSqrt().cwiseInverse();
    const Eigen::MatrixXd s = d.asDiagonal() * w * d.asDiagonal();
    for (int i = 0; i < size; ++i) {
      for (int j = 0; j < size; ++j) {
        if (s(i, j) != 0) triplets.emplace_back(b * size + i, b * size + j, s(i, j));
      }
    }
  }
  Eigen::SparseMatrix<double> matrix(blocks * size, blocks * size);
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  return matrix;
}

TEST(LanczosTopEigenvectors, FindsEveryCopyOfARepeatedTopEigenvalue) {
  const Eigen::SparseMatrix<double> matrix = RepeatedBlocks(5, 40);
  const Eigen::MatrixXd vectors = LanczosTopEigenvectors(matrix, 5, {});
  ASSERT_EQ(vectors.cols(), 5);
  // Each column is an eigenvector of eigenvalue 1 and the five span the whole eigenspace.
  for (int c = 0; c < 5; ++c) {
    const Eigen::VectorXd v = vectors.col(c);
    EXPECT_NEAR(v.norm(), 1.0, 1e-9);
    EXPECT_LT((matrix * v - v).norm(), 1e-7) << "column " << c;
  }
  EXPECT_LT((vectors.transpose() * vectors - Eigen::MatrixXd::Identity(5, 5)).norm(), 1e-7);
}

TEST(LanczosTopEigenvectors, AgreesWithTheDenseSolver) {
  // Top 7 of 3 blocks: the 3 copies of 1, the 3 copies of the second eigenvalue, one of the third.
  const Eigen::SparseMatrix<double> matrix = RepeatedBlocks(3, 30);
  const Eigen::MatrixXd vectors = LanczosTopEigenvectors(matrix, 7, {});
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> dense((Eigen::MatrixXd(matrix)));
  const Eigen::VectorXd expected = dense.eigenvalues().reverse().head(7);
  for (int c = 0; c < 7; ++c) {
    const double rayleigh = vectors.col(c).dot(matrix * vectors.col(c));
    EXPECT_NEAR(rayleigh, expected[c], 1e-8) << "eigenpair " << c;
  }
}

TEST(LanczosTopEigenvectors, RejectsBadCounts) {
  const Eigen::SparseMatrix<double> matrix = RepeatedBlocks(1, 10);
  EXPECT_THROW(LanczosTopEigenvectors(matrix, 0, {}), std::invalid_argument);
  EXPECT_THROW(LanczosTopEigenvectors(matrix, 10, {}), std::invalid_argument);
}

}  // namespace
}  // namespace avc::cluster::baselines
