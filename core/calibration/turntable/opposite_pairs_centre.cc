#include "core/calibration/turntable/opposite_pairs_centre.h"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <stdexcept>

namespace avc::calibration {
namespace {

constexpr const char* kMethod = "turntable line intersection";

// Angle difference b - a wrapped to (-pi, pi].
double WrappedDifference(double a, double b) {
  double d = std::remainder(b - a, 2 * M_PI);
  if (d <= -M_PI) d += 2 * M_PI;
  return d;
}

}  // namespace

TurntableAxis OppositePairsCentre(const std::vector<TurntableView>& views,
                                  const OppositePairsOptions& options) {
  ValidateTurntableViews(views, options.limits, kMethod);
  // Pair each view with its first unused opposite, in input order (deterministic).
  std::vector<bool> used(views.size(), false);
  std::vector<std::pair<size_t, size_t>> pairs;
  for (size_t i = 0; i < views.size(); ++i) {
    if (used[i]) continue;
    for (size_t j = i + 1; j < views.size(); ++j) {
      if (used[j]) continue;
      const double off =
          std::abs(std::abs(WrappedDifference(views[i].angle, views[j].angle)) - M_PI);
      if (off <= options.pair_tolerance) {
        used[i] = used[j] = true;
        pairs.emplace_back(i, j);
        break;
      }
    }
  }
  if (pairs.size() < 2)
    throw std::invalid_argument(fmt::format(
        "{}: {} pair(s) of opposite table angles (180 +- {:.2f} deg) found, at least 2 needed",
        kMethod, pairs.size(), options.pair_tolerance * 180 / M_PI));

  // Least-squares intersection: minimise the summed squared distance to every line,
  // sum_k (I - d_k d_k^T) (x - p_k) = 0.
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> directions;
  for (const auto& [i, j] : pairs) {
    const Eigen::Vector3d p = views[i].T_fixed_board.translation();
    const Eigen::Vector3d q = views[j].T_fixed_board.translation();
    if ((q - p).norm() < 1e-9)
      throw std::invalid_argument(fmt::format(
          "{}: the board origin does not move between views {} and {} (it sits on the axis)",
          kMethod, i, j));
    const Eigen::Vector3d d = (q - p).normalized();
    directions.push_back(d);
    const Eigen::Matrix3d projector = Eigen::Matrix3d::Identity() - d * d.transpose();
    A += projector;
    b += projector * p;
  }
  double widest = 0;
  for (size_t m = 0; m < directions.size(); ++m) {
    for (size_t n = m + 1; n < directions.size(); ++n)
      widest =
          std::max(widest, std::acos(std::min(1.0, std::abs(directions[m].dot(directions[n])))));
  }
  if (widest < options.min_line_angle)
    throw std::invalid_argument(fmt::format(
        "{}: the opposite-pair lines are within {:.2f} deg of parallel; no intersection", kMethod,
        widest * 180 / M_PI));

  TurntableAxis result;
  result.centre = A.ldlt().solve(b);
  // Plane through the paired origins: its normal is the smallest-eigenvalue direction of their
  // scatter.
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  int count = 0;
  for (const auto& [i, j] : pairs) {
    mean += views[i].T_fixed_board.translation() + views[j].T_fixed_board.translation();
    count += 2;
  }
  mean /= count;
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const auto& [i, j] : pairs) {
    for (size_t k : {i, j}) {
      const Eigen::Vector3d d = views[k].T_fixed_board.translation() - mean;
      scatter += d * d.transpose();
    }
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(scatter);
  Eigen::Vector3d normal = eigen.eigenvectors().col(0);
  // Orient right-handed for positive angles: origins must turn counter-clockwise about it.
  double turning = 0;
  for (size_t k = 0; k < views.size(); ++k) {
    for (size_t l = 0; l < views.size(); ++l) {
      const double s = std::sin(views[l].angle - views[k].angle);
      const Eigen::Vector3d u = views[k].T_fixed_board.translation() - result.centre;
      const Eigen::Vector3d v = views[l].T_fixed_board.translation() - result.centre;
      turning += s * u.cross(v).dot(normal);
    }
  }
  result.axis = turning < 0 ? -normal : normal;
  return result;
}

}  // namespace avc::calibration
