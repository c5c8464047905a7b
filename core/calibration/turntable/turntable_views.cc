#include "core/calibration/turntable/turntable_views.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/geometry/rigid_transform.h"

namespace avc::calibration {

double AngularSpan(const std::vector<double>& angles) {
  if (angles.size() < 2) return 0;
  std::vector<double> wrapped;
  for (double a : angles) {
    double w = std::fmod(a, 2 * M_PI);
    if (w < 0) w += 2 * M_PI;
    wrapped.push_back(w);
  }
  std::sort(wrapped.begin(), wrapped.end());
  // The span is the circle minus the largest empty gap between neighbouring angles.
  double largest_gap = wrapped.front() + 2 * M_PI - wrapped.back();
  for (size_t i = 1; i < wrapped.size(); ++i)
    largest_gap = std::max(largest_gap, wrapped[i] - wrapped[i - 1]);
  return 2 * M_PI - largest_gap;
}

void ValidateTurntableViews(const std::vector<TurntableView>& views,
                            const TurntableInputLimits& limits, const std::string& method) {
  const int min_views = std::max(limits.min_views, 3);
  if (static_cast<int>(views.size()) < min_views)
    throw std::invalid_argument(fmt::format("{}: {} table angles given, at least {} needed", method,
                                            views.size(), min_views));
  std::vector<double> angles;
  for (size_t i = 0; i < views.size(); ++i) {
    const TurntableView& view = views[i];
    if (!std::isfinite(view.angle))
      throw std::invalid_argument(fmt::format("{}: view {} has a non-finite angle", method, i));
    if (auto problem = geometry::RigidTransformProblem(
            view.T_fixed_board, fmt::format("{}: view {} T_fixed_board", method, i));
        !problem.empty()) {
      throw std::invalid_argument(problem);
    }
    angles.push_back(view.angle);
  }
  const double span = AngularSpan(angles);
  if (span < limits.min_span)
    throw std::invalid_argument(fmt::format(
        "{}: the table angles span {:.1f} deg, at least {:.1f} deg needed to fix the axis", method,
        span * 180 / M_PI, limits.min_span * 180 / M_PI));
}

Eigen::Isometry3d TableFrame(const TurntableAxis& axis,
                             const Eigen::Vector3d& board_origin_at_zero) {
  const Eigen::Vector3d z = axis.axis.normalized();
  Eigen::Vector3d x = board_origin_at_zero - axis.centre;
  x -= z * z.dot(x);
  if (x.norm() < 1e-9) x = z.unitOrthogonal();  // board origin on the axis: any x will do
  x.normalize();
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() << x, z.cross(x), z;
  T.translation() = axis.centre;
  return T;
}

Eigen::Isometry3d RotationAboutLine(const Eigen::Vector3d& axis, const Eigen::Vector3d& centre,
                                    double angle) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
  T.translation() = centre - T.linear() * centre;
  return T;
}

}  // namespace avc::calibration
