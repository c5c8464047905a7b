#include "bench/clustering/baselines/kmeans_rows.h"

#include <fmt/format.h>

#include <limits>
#include <random>
#include <stdexcept>

namespace avc::cluster::baselines {
namespace {

// Uniform in [0, 1) from the top 53 bits: the same on every standard library.
double Uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

struct Run {
  std::vector<int32_t> labels;
  double inertia = std::numeric_limits<double>::infinity();
};

Eigen::MatrixXd SeedPlusPlus(const Eigen::MatrixXd& rows, int k, std::mt19937_64& rng) {
  const Eigen::Index n = rows.rows();
  Eigen::MatrixXd centres(k, rows.cols());
  centres.row(0) = rows.row(static_cast<Eigen::Index>(Uniform(rng) * static_cast<double>(n)));
  Eigen::VectorXd nearest = (rows.rowwise() - centres.row(0)).rowwise().squaredNorm();
  for (int c = 1; c < k; ++c) {
    const double total = nearest.sum();
    Eigen::Index pick = 0;
    if (total > 0) {
      // Sample proportionally to squared distance to the nearest chosen centre.
      double target = Uniform(rng) * total;
      for (pick = 0; pick < n - 1; ++pick) {
        target -= nearest[pick];
        if (target < 0) break;
      }
    } else {
      pick = static_cast<Eigen::Index>(Uniform(rng) * static_cast<double>(n));
    }
    centres.row(c) = rows.row(pick);
    nearest = nearest.cwiseMin((rows.rowwise() - centres.row(c)).rowwise().squaredNorm());
  }
  return centres;
}

Run Lloyd(const Eigen::MatrixXd& rows, Eigen::MatrixXd centres, int max_iterations) {
  const Eigen::Index n = rows.rows();
  const int k = static_cast<int>(centres.rows());
  Run run;
  run.labels.assign(static_cast<size_t>(n), -1);
  Eigen::VectorXd distance(n);
  for (int iteration = 0; iteration < max_iterations; ++iteration) {
    bool changed = false;
    for (Eigen::Index i = 0; i < n; ++i) {
      int best = 0;
      double best_d = std::numeric_limits<double>::infinity();
      for (int c = 0; c < k; ++c) {
        const double d = (rows.row(i) - centres.row(c)).squaredNorm();
        if (d < best_d) best_d = d, best = c;
      }
      distance[i] = best_d;
      if (run.labels[i] != best) run.labels[i] = best, changed = true;
    }
    if (!changed) break;
    Eigen::MatrixXd sums = Eigen::MatrixXd::Zero(k, rows.cols());
    std::vector<int> counts(static_cast<size_t>(k), 0);
    for (Eigen::Index i = 0; i < n; ++i) {
      sums.row(run.labels[i]) += rows.row(i);
      ++counts[static_cast<size_t>(run.labels[i])];
    }
    for (int c = 0; c < k; ++c) {
      if (counts[static_cast<size_t>(c)] > 0) {
        centres.row(c) = sums.row(c) / counts[static_cast<size_t>(c)];
      } else {
        // An emptied cluster restarts at the point worst served by the others.
        Eigen::Index worst = 0;
        distance.maxCoeff(&worst);
        centres.row(c) = rows.row(worst);
        distance[worst] = 0;
      }
    }
  }
  run.inertia = distance.sum();
  return run;
}

}  // namespace

std::vector<int32_t> KMeansRows(const Eigen::MatrixXd& rows, const KMeansRowsOptions& options) {
  if (options.clusters < 1 || options.clusters > rows.rows()) {
    throw std::invalid_argument(
        fmt::format("KMeansRows: {} clusters for {} rows", options.clusters, rows.rows()));
  }
  if (options.restarts < 1 || options.max_iterations < 1) {
    throw std::invalid_argument("KMeansRows: restarts and max_iterations must be positive");
  }
  if (!rows.allFinite()) throw std::invalid_argument("KMeansRows: rows are not finite");
  std::mt19937_64 rng(options.seed);
  Run best;
  for (int restart = 0; restart < options.restarts; ++restart) {
    Run run = Lloyd(rows, SeedPlusPlus(rows, options.clusters, rng), options.max_iterations);
    if (run.inertia < best.inertia) best = std::move(run);
  }
  return best.labels;
}

}  // namespace avc::cluster::baselines
