#include "bench/clustering/baselines/spectral_embedding.h"

#include <algorithm>

#include "bench/clustering/baselines/kmeans_rows.h"
#include "bench/clustering/baselines/relabel.h"

namespace avc::cluster::baselines {

double MedianDistance(std::vector<double> kth_neighbour_distances) {
  if (kth_neighbour_distances.empty()) return 1.0;
  auto middle = kth_neighbour_distances.begin() +
                static_cast<std::ptrdiff_t>(kth_neighbour_distances.size() / 2);
  std::nth_element(kth_neighbour_distances.begin(), middle, kth_neighbour_distances.end());
  return *middle > 0 ? *middle : 1.0;
}

Assignment ClusterEmbedding(Eigen::MatrixXd eigenvectors, int clusters, int restarts,
                            uint64_t seed) {
  for (Eigen::Index i = 0; i < eigenvectors.rows(); ++i) {
    const double norm = eigenvectors.row(i).norm();
    // An isolated point has a zero row; it stays at the origin rather than dividing by zero.
    if (norm > 0) eigenvectors.row(i) /= norm;
  }
  KMeansRowsOptions options;
  options.clusters = clusters;
  options.restarts = restarts;
  options.seed = seed;
  return RelabelByFirstAppearance(KMeansRows(eigenvectors, options));
}

}  // namespace avc::cluster::baselines
