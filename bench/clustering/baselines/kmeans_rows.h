#pragma once

// Seeded k-means++ / Lloyd on the rows of a matrix: the k-means baseline (on xyz) and the last
// step of spectral clustering (on the embedding). Our own so results are bit-identical across
// library versions (no std distributions, no OpenCV RNG).

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace avc::cluster::baselines {

struct KMeansRowsOptions {
  int clusters = 8;
  int restarts = 5;  // independent k-means++ seedings; the lowest inertia wins
  int max_iterations = 100;
  uint64_t seed = 1;
};

// A cluster id in [0, clusters) per row. Requires 1 <= clusters <= rows.rows().
std::vector<int32_t> KMeansRows(const Eigen::MatrixXd& rows, const KMeansRowsOptions& options);

}  // namespace avc::cluster::baselines
