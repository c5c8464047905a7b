#pragma once

// Steps shared by the dense and sparse spectral baselines (Ng, Jordan & Weiss 2002).

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/cluster/point_set.h"

namespace avc::cluster::baselines {

// The Gaussian affinity's scale: the median over points of the distance to their k-th nearest
// neighbour, so sigma follows the sampling density. Falls back to 1 when every distance is 0.
double MedianDistance(std::vector<double> kth_neighbour_distances);

// NJW's last steps: row-normalise the n x K top eigenvectors and run seeded k-means on the rows.
Assignment ClusterEmbedding(Eigen::MatrixXd eigenvectors, int clusters, int restarts,
                            uint64_t seed);

}  // namespace avc::cluster::baselines
