#include "bench/clustering/baselines/kmeans.h"

#include "bench/clustering/baselines/input_checks.h"
#include "bench/clustering/baselines/kmeans_rows.h"
#include "bench/clustering/baselines/relabel.h"

namespace avc::cluster::baselines {

Assignment KMeansClustering(const PointSet& set, const KMeansOptions& options) {
  CheckPoints(set, "k-means");
  CheckClusterCount(options.clusters, set.points.size(), "k-means");
  Eigen::MatrixXd rows(static_cast<Eigen::Index>(set.points.size()), 3);
  for (size_t i = 0; i < set.points.size(); ++i) {
    rows.row(static_cast<Eigen::Index>(i)) = set.points[i].cast<double>().transpose();
  }
  return RelabelByFirstAppearance(
      KMeansRows(rows, {options.clusters, options.restarts, options.max_iterations, options.seed}));
}

}  // namespace avc::cluster::baselines
