#include "core/calibration/hand_eye/reprojection_refinement.h"

#include <ceres/ceres.h>
#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "core/calibration/hand_eye/refinement_residuals.h"
#include "core/geometry/rigid_transform.h"

namespace avc::calibration::hand_eye {
namespace {

void CheckViews(const std::vector<BoardView>& views) {
  if (views.empty()) throw std::invalid_argument("hand-eye refinement: no views");
  for (size_t i = 0; i < views.size(); ++i) {
    const BoardView& view = views[i];
    const std::string error =
        geometry::RigidTransformProblem(view.T_base_flange, fmt::format("view {} pose", i));
    if (!error.empty()) throw std::invalid_argument("hand-eye refinement: " + error);
    if (view.board_points.empty() || view.board_points.size() != view.pixels.size()) {
      throw std::invalid_argument(
          fmt::format("hand-eye refinement: view {} has {} board points and {} pixels (need as "
                      "many, at least one)",
                      i, view.board_points.size(), view.pixels.size()));
    }
    for (size_t k = 0; k < view.pixels.size(); ++k) {
      if (!view.board_points[k].allFinite() || !view.pixels[k].allFinite()) {
        throw std::invalid_argument(
            fmt::format("hand-eye refinement: view {} corner {} is not finite", i, k));
      }
    }
  }
}

double Rms(double sum_squared, size_t count) {
  return count == 0 ? 0 : std::sqrt(sum_squared / static_cast<double>(count));
}

}  // namespace

std::vector<double> ViewReprojectionRms(const std::vector<BoardView>& views,
                                        const camera::Intrinsics& intrinsics,
                                        const Eigen::Isometry3d& T_board_base,
                                        const Eigen::Isometry3d& T_cam_flange) {
  const Eigen::Isometry3d T_base_board = T_board_base.inverse();
  std::vector<double> rms;
  for (const BoardView& view : views) {
    const Eigen::Isometry3d T_cam_board =
        T_cam_flange * view.T_base_flange.inverse() * T_base_board;
    double sum_squared = 0;
    for (size_t k = 0; k < view.board_points.size(); ++k) {
      const auto pixel = intrinsics.Project(T_cam_board * view.board_points[k]);
      sum_squared +=
          pixel ? (*pixel - view.pixels[k]).squaredNorm() : std::numeric_limits<double>::infinity();
    }
    rms.push_back(Rms(sum_squared, view.board_points.size()));
  }
  return rms;
}

RefinementResult RefineOnReprojection(const std::vector<BoardView>& views,
                                      const camera::Intrinsics& intrinsics,
                                      const Eigen::Isometry3d& T_board_base_start,
                                      const Eigen::Isometry3d& T_cam_flange_start,
                                      const RefinementOptions& options) {
  if (std::string error = intrinsics.Validate(); !error.empty()) {
    throw std::invalid_argument("hand-eye refinement: camera " + error);
  }
  if (!(options.huber_px >= 0) || !std::isfinite(options.huber_px) || options.max_iterations < 1) {
    throw std::invalid_argument(
        "hand-eye refinement: huber_px must be finite and >= 0 and max_iterations >= 1");
  }
  const bool correct_robot =
      options.robot_rotation_sigma_deg > 0 || options.robot_translation_sigma_mm > 0;
  if (!std::isfinite(options.robot_rotation_sigma_deg) ||
      !std::isfinite(options.robot_translation_sigma_mm) ||
      (correct_robot &&
       !(options.robot_rotation_sigma_deg > 0 && options.robot_translation_sigma_mm > 0 &&
         options.pixel_sigma_px > 0 && std::isfinite(options.pixel_sigma_px)))) {
    throw std::invalid_argument(
        "hand-eye refinement: robot_rotation_sigma_deg and robot_translation_sigma_mm must both "
        "be 0 (robot poses exact) or both > 0 with a finite pixel_sigma_px > 0");
  }
  CheckViews(views);
  for (const auto& [pose, name] : {std::pair{&T_board_base_start, "start T_board_base"},
                                   std::pair{&T_cam_flange_start, "start T_cam_flange"}}) {
    if (std::string error = geometry::RigidTransformProblem(*pose, name); !error.empty()) {
      throw std::invalid_argument("hand-eye refinement: " + error);
    }
  }

  RefinementResult result;
  const std::vector<double> initial =
      ViewReprojectionRms(views, intrinsics, T_board_base_start, T_cam_flange_start);
  double initial_sum = 0;
  size_t corner_count = 0;
  for (size_t i = 0; i < views.size(); ++i) {
    if (!std::isfinite(initial[i])) {
      throw std::invalid_argument(fmt::format(
          "hand-eye refinement: at the start a corner of view {} is behind the camera", i));
    }
    initial_sum += initial[i] * initial[i] * static_cast<double>(views[i].pixels.size());
    corner_count += views[i].pixels.size();
  }
  result.initial_rms_px = Rms(initial_sum, corner_count);

  const Eigen::Isometry3d T_base_board_start = T_board_base_start.inverse();
  Eigen::Quaterniond q_cam_flange(T_cam_flange_start.linear());
  Eigen::Vector3d t_cam_flange = T_cam_flange_start.translation();
  Eigen::Quaterniond q_base_board(T_base_board_start.linear());
  Eigen::Vector3d t_base_board = T_base_board_start.translation();

  // One (rotation vector, translation) correction per view, starting at zero.
  std::vector<Eigen::Matrix<double, 6, 1>> corrections(views.size(),
                                                       Eigen::Matrix<double, 6, 1>::Zero());
  ceres::Problem problem;
  for (size_t i = 0; i < views.size(); ++i) {
    const BoardView& view = views[i];
    for (size_t k = 0; k < view.pixels.size(); ++k) {
      auto* cost = new ceres::AutoDiffCostFunction<CornerResidual, 2, 4, 3, 4, 3, 6>(
          new CornerResidual(intrinsics, view.T_base_flange, view.board_points[k], view.pixels[k]));
      ceres::LossFunction* loss =
          options.huber_px > 0 ? new ceres::HuberLoss(options.huber_px) : nullptr;
      problem.AddResidualBlock(cost, loss, q_cam_flange.coeffs().data(), t_cam_flange.data(),
                               q_base_board.coeffs().data(), t_base_board.data(),
                               corrections[i].data());
    }
    if (correct_robot) {
      const double rotation_sigma_rad = options.robot_rotation_sigma_deg * std::numbers::pi / 180;
      const double translation_sigma_m = options.robot_translation_sigma_mm * 1e-3;
      problem.AddResidualBlock(
          new ceres::AutoDiffCostFunction<RobotPosePrior, 6, 6>(
              new RobotPosePrior(options.pixel_sigma_px / rotation_sigma_rad,
                                 options.pixel_sigma_px / translation_sigma_m)),
          nullptr, corrections[i].data());
    } else {
      problem.SetParameterBlockConstant(corrections[i].data());
    }
  }
  problem.SetManifold(q_cam_flange.coeffs().data(), new ceres::EigenQuaternionManifold);
  problem.SetManifold(q_base_board.coeffs().data(), new ceres::EigenQuaternionManifold);

  ceres::Solver::Options solver_options;
  solver_options.linear_solver_type = ceres::DENSE_SCHUR;
  solver_options.max_num_iterations = options.max_iterations;
  solver_options.function_tolerance = 1e-14;
  solver_options.gradient_tolerance = 1e-16;
  solver_options.parameter_tolerance = 1e-14;
  solver_options.num_threads = 1;  // one thread: the same bits every run
  solver_options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(solver_options, &problem, &summary);
  if (summary.termination_type == ceres::FAILURE) {
    throw std::runtime_error("hand-eye refinement: Ceres failed: " + summary.message);
  }

  result.T_cam_flange.linear() = q_cam_flange.normalized().toRotationMatrix();
  result.T_cam_flange.translation() = t_cam_flange;
  Eigen::Isometry3d T_base_board = Eigen::Isometry3d::Identity();
  T_base_board.linear() = q_base_board.normalized().toRotationMatrix();
  T_base_board.translation() = t_base_board;
  result.T_board_base = T_base_board.inverse();
  result.view_rms_px =
      ViewReprojectionRms(views, intrinsics, result.T_board_base, result.T_cam_flange);
  double final_sum = 0;
  for (size_t i = 0; i < views.size(); ++i) {
    final_sum +=
        result.view_rms_px[i] * result.view_rms_px[i] * static_cast<double>(views[i].pixels.size());
  }
  result.rms_px = Rms(final_sum, corner_count);
  for (const Eigen::Matrix<double, 6, 1>& correction : corrections) {
    result.view_robot_correction_deg.push_back(correction.head<3>().norm() * 180 /
                                               std::numbers::pi);
    result.view_robot_correction_mm.push_back(correction.tail<3>().norm() * 1e3);
  }
  result.iterations = static_cast<int>(summary.iterations.size());
  result.converged = summary.termination_type == ceres::CONVERGENCE;
  result.solver_report = summary.BriefReport();
  return result;
}

}  // namespace avc::calibration::hand_eye
