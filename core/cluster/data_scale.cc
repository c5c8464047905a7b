#include "core/cluster/data_scale.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/cluster/point_grid.h"
#include "core/util/upper_median.h"

namespace avc::cluster {
namespace {

// Nearest-neighbour distances, searching within radius; infinity where none was found.
std::vector<double> NearestDistances(const std::vector<Eigen::Vector3f>& points, float radius) {
  const PointGrid grid(points, radius);
  std::vector<double> nearest(points.size(), std::numeric_limits<double>::infinity());
  for (size_t i = 0; i < points.size(); ++i) {
    float best = std::numeric_limits<float>::infinity();
    grid.ForEachWithin(points[i], radius, [&](uint32_t j) {
      if (j != i) best = std::min(best, (points[j] - points[i]).squaredNorm());
    });
    if (best > 0.0f && std::isfinite(best)) nearest[i] = std::sqrt(best);
  }
  return nearest;
}

}  // namespace

DataScale EstimateDataScale(const std::vector<Eigen::Vector3f>& points) {
  if (points.size() < 3) {
    throw std::invalid_argument("EstimateDataScale: need at least 3 points, got " +
                                std::to_string(points.size()));
  }
  Eigen::Vector3f lo = points[0];
  Eigen::Vector3f hi = points[0];
  for (const Eigen::Vector3f& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double diagonal = (hi - lo).norm();
  if (!(diagonal > 0.0)) throw std::invalid_argument("EstimateDataScale: all points coincide");

  // A surface of n samples inside a box of diagonal d has spacing of order d / sqrt(n); search
  // there first and widen until most points found a neighbour (coincident pairs are ignored).
  DataScale scale;
  float radius = static_cast<float>(diagonal / std::sqrt(static_cast<double>(points.size())));
  for (int attempt = 0; attempt < 20; ++attempt, radius *= 2.0f) {
    const std::vector<double> nearest = NearestDistances(points, radius);
    const double median = UpperMedian(nearest);
    if (std::isfinite(median)) {
      scale.spacing = median;
      break;
    }
  }
  if (!(scale.spacing > 0.0)) throw std::invalid_argument("EstimateDataScale: no point spacing");

  // Local plane residuals on a deterministic subsample (every stride-th point) for speed.
  const float fit_radius = static_cast<float>(2.5 * scale.spacing);
  const PointGrid grid(points, fit_radius);
  const size_t stride = std::max<size_t>(1, points.size() / 1000);
  std::vector<double> residuals;
  std::vector<uint32_t> neighbours;
  for (size_t i = 0; i < points.size(); i += stride) {
    neighbours.clear();
    grid.ForEachWithin(points[i], fit_radius, [&](uint32_t j) { neighbours.push_back(j); });
    if (neighbours.size() < 5) continue;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (uint32_t j : neighbours) mean += points[j].cast<double>();
    mean /= static_cast<double>(neighbours.size());
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for (uint32_t j : neighbours) {
      const Eigen::Vector3d d = points[j].cast<double>() - mean;
      covariance.noalias() += d * d.transpose();
    }
    covariance /= static_cast<double>(neighbours.size());
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
    solver.computeDirect(covariance, Eigen::EigenvaluesOnly);
    residuals.push_back(std::sqrt(std::max(0.0, solver.eigenvalues()[0])));
  }
  scale.noise = residuals.empty() ? 0.0 : UpperMedian(residuals);
  return scale;
}

}  // namespace avc::cluster
