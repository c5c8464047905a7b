#include "core/calibration/turntable/turntable_axis_fit.h"

#include <ceres/ceres.h>
#include <ceres/line_manifold.h>
#include <ceres/rotation.h>
#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace avc::calibration {
namespace {

constexpr const char* kCeresFit = "turntable Ceres fit";

// Rotation matrix (column-major 3x3) for rotation vector `w`.
template <typename T>
Eigen::Matrix<T, 3, 3> Exp(const T* w) {
  Eigen::Matrix<T, 3, 3> R;
  ceres::AngleAxisToRotationMatrix(w, ceres::ColumnMajorAdapter3x3(R.data()));
  return R;
}

// One view: the board pose predicted from the axis line, the angle-0 pose and the angle.
struct ViewResidual {
  ViewResidual(const TurntableView& view, const Eigen::Matrix3d& board_rotation_start,
               const TurntableFitOptions& options)
      : angle(view.angle),
        R_measured(view.T_fixed_board.linear()),
        p_measured(view.T_fixed_board.translation()),
        R0_start(board_rotation_start),
        position_weight(1 / options.position_sigma),
        orientation_weight(1 / options.orientation_sigma) {}

  template <typename T>
  bool operator()(const T* line, const T* board_update, const T* board_origin, const T* offset,
                  T* residual) const {
    using Vec3 = Eigen::Matrix<T, 3, 1>;
    const Eigen::Map<const Vec3> c(line), a(line + 3), p0(board_origin);
    const T theta = T(angle) + offset[0];
    const Vec3 axis_angle = a * theta;
    const Eigen::Matrix<T, 3, 3> turn = Exp(axis_angle.data());
    const Vec3 p = c + turn * (p0 - c);
    const Eigen::Matrix<T, 3, 3> R = turn * R0_start.cast<T>() * Exp(board_update);
    // Orientation error in the board frame: log(R_measured^T R).
    const Eigen::Matrix<T, 3, 3> error = R_measured.transpose().cast<T>() * R;
    T rotation_error[3];
    ceres::RotationMatrixToAngleAxis(ceres::ColumnMajorAdapter3x3(error.data()), rotation_error);
    for (int i = 0; i < 3; ++i) {
      residual[i] = T(position_weight) * (p(i) - T(p_measured(i)));
      residual[3 + i] = T(orientation_weight) * rotation_error[i];
    }
    return true;
  }

  double angle;
  Eigen::Matrix3d R_measured;
  Eigen::Vector3d p_measured;
  Eigen::Matrix3d R0_start;
  double position_weight;
  double orientation_weight;
};

struct AnglePrior {
  double weight;
  template <typename T>
  bool operator()(const T* offset, T* residual) const {
    residual[0] = T(weight) * offset[0];
    return true;
  }
};

}  // namespace

TurntableFit FitTurntableAxis(const std::vector<TurntableView>& views,
                              const TurntableFitOptions& options) {
  if (!(options.position_sigma > 0) || !(options.orientation_sigma > 0) ||
      !(options.angle_sigma >= 0) || options.max_iterations < 1)
    throw std::invalid_argument(fmt::format(
        "{}: noise sigmas must be positive (angle_sigma >= 0) and max_iterations >= 1", kCeresFit));
  ValidateTurntableViews(views, options.limits, kCeresFit);
  const TurntableAxis start = CircleScrewAxis(views, {options.limits});

  // Board pose at angle 0 from the first view turned back by its commanded angle.
  const Eigen::Isometry3d T0 = RotationAboutLine(start.axis, start.centre, -views.front().angle) *
                               views.front().T_fixed_board;
  const Eigen::Matrix3d R0_start = T0.linear();
  double line[6] = {start.centre.x(), start.centre.y(), start.centre.z(),
                    start.axis.x(),   start.axis.y(),   start.axis.z()};
  double board_update[3] = {0, 0, 0};
  double board_origin[3] = {T0.translation().x(), T0.translation().y(), T0.translation().z()};
  std::vector<double> offsets(views.size(), 0.0);

  ceres::Problem problem;
  problem.AddParameterBlock(line, 6, new ceres::LineManifold<3>());
  for (size_t k = 0; k < views.size(); ++k) {
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<ViewResidual, 6, 6, 3, 3, 1>(
                                 new ViewResidual(views[k], R0_start, options)),
                             nullptr, line, board_update, board_origin, &offsets[k]);
    if (options.angle_sigma > 0) {
      problem.AddResidualBlock(new ceres::AutoDiffCostFunction<AnglePrior, 1, 1>(
                                   new AnglePrior{1 / options.angle_sigma}),
                               nullptr, &offsets[k]);
    } else {
      problem.SetParameterBlockConstant(&offsets[k]);
    }
  }
  ceres::Solver::Options solver;
  solver.linear_solver_type = ceres::DENSE_QR;
  solver.max_num_iterations = options.max_iterations;
  solver.num_threads = 1;
  solver.function_tolerance = 1e-14;
  solver.gradient_tolerance = 1e-14;
  solver.parameter_tolerance = 1e-14;
  solver.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(solver, &problem, &summary);
  if (!summary.IsSolutionUsable())
    throw std::runtime_error(fmt::format("{}: solver failed: {}", kCeresFit, summary.message));

  TurntableFit fit;
  const Eigen::Vector3d c(line[0], line[1], line[2]);
  const Eigen::Vector3d a = Eigen::Vector3d(line[3], line[4], line[5]).normalized();
  const Eigen::Vector3d p0(board_origin[0], board_origin[1], board_origin[2]);
  fit.axis.axis = a;
  // The manifold lets the line's origin slide along the axis; report the foot of the board
  // origin, the same point the circle fit gives.
  fit.axis.centre = c + a * a.dot(p0 - c);
  fit.T_fixed_board0.linear() = R0_start * Exp(board_update);
  fit.T_fixed_board0.translation() = p0;
  fit.angle_offsets = offsets;
  fit.iterations = static_cast<int>(summary.iterations.size());
  double position_sum = 0, orientation_sum = 0;
  for (size_t k = 0; k < views.size(); ++k) {
    const Eigen::Isometry3d predicted =
        RotationAboutLine(a, fit.axis.centre, views[k].angle + offsets[k]) * fit.T_fixed_board0;
    position_sum += (predicted.translation() - views[k].T_fixed_board.translation()).squaredNorm();
    const Eigen::AngleAxisd error(views[k].T_fixed_board.linear().transpose() * predicted.linear());
    orientation_sum += error.angle() * error.angle();
  }
  fit.rms_position = std::sqrt(position_sum / static_cast<double>(views.size()));
  fit.rms_orientation = std::sqrt(orientation_sum / static_cast<double>(views.size()));
  return fit;
}

}  // namespace avc::calibration
