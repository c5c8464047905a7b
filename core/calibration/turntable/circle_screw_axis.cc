#include "core/calibration/turntable/circle_screw_axis.h"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <cmath>
#include <stdexcept>

namespace avc::calibration {
namespace {

constexpr const char* kCircleScrewFit = "turntable circle/screw fit";

Eigen::Vector3d SkewPart(const Eigen::Matrix3d& R) {
  return 0.5 * Eigen::Vector3d(R(2, 1) - R(1, 2), R(0, 2) - R(2, 0), R(1, 0) - R(0, 1));
}

Eigen::Vector3d AxisFromRotations(const std::vector<TurntableView>& views) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (size_t k = 0; k < views.size(); ++k) {
    for (size_t l = k + 1; l < views.size(); ++l) {
      const Eigen::Matrix3d relative =
          views[l].T_fixed_board.linear() * views[k].T_fixed_board.linear().transpose();
      sum += std::sin(views[l].angle - views[k].angle) * SkewPart(relative);
    }
  }
  if (sum.norm() < 1e-9)
    throw std::invalid_argument(fmt::format(
        "{}: the board orientations do not rotate with the commanded angles", kCircleScrewFit));
  return sum.normalized();
}

}  // namespace

TurntableAxis CircleScrewAxis(const std::vector<TurntableView>& views,
                              const CircleScrewOptions& options) {
  ValidateTurntableViews(views, options.limits, kCircleScrewFit);
  TurntableAxis result;
  result.axis = AxisFromRotations(views);
  const Eigen::Vector3d& a = result.axis;
  const Eigen::Vector3d u = a.unitOrthogonal();
  const Eigen::Vector3d v = a.cross(u);

  // Kasa fit in the plane (u, v): |q|^2 = 2 q.c + k with k = r^2 - |c|^2, linear in (c, k).
  // Coordinates are taken relative to the mean origin to keep the system well scaled.
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& view : views) mean += view.T_fixed_board.translation();
  mean /= static_cast<double>(views.size());
  const int n = static_cast<int>(views.size());
  Eigen::MatrixXd A(n, 3);
  Eigen::VectorXd b(n);
  double height = 0;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d d = views[static_cast<size_t>(i)].T_fixed_board.translation() - mean;
    const Eigen::Vector2d q(d.dot(u), d.dot(v));
    A.row(i) << 2 * q.x(), 2 * q.y(), 1;
    b(i) = q.squaredNorm();
    height += d.dot(a);
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
  if (qr.rank() < 3)
    throw std::invalid_argument(fmt::format(
        "{}: the board origins are collinear in the plane normal to the axis", kCircleScrewFit));
  const Eigen::Vector3d solution = qr.solve(b);
  const double radius_squared = solution.z() + solution.head<2>().squaredNorm();
  if (!solution.allFinite() || !(radius_squared > 1e-12))
    throw std::invalid_argument(fmt::format(
        "{}: the board origin does not travel on a circle (is it on the axis?)", kCircleScrewFit));
  result.centre = mean + solution.x() * u + solution.y() * v + (height / n) * a;
  return result;
}

}  // namespace avc::calibration
