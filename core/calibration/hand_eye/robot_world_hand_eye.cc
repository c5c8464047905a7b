#include "core/calibration/hand_eye/robot_world_hand_eye.h"

#include <fmt/format.h>

#include <numbers>

#include "core/calibration/hand_eye/rotation_solve.h"
#include "core/calibration/hand_eye/translation_solve.h"
#include "core/geometry/rigid_transform.h"

namespace avc::calibration::hand_eye {

void CheckObservations(const std::vector<HandEyeObservation>& observations) {
  for (size_t i = 0; i < observations.size(); ++i) {
    for (const auto& [pose, field] : {std::pair{&observations[i].T_base_flange, "T_base_flange"},
                                      std::pair{&observations[i].T_cam_board, "T_cam_board"}}) {
      const std::string error =
          geometry::RigidTransformProblem(*pose, fmt::format("observation {} {}", i, field));
      if (!error.empty()) throw std::invalid_argument("hand-eye calibration: " + error);
    }
  }
}

std::vector<PoseResidual> PoseResiduals(const std::vector<HandEyeObservation>& observations,
                                        const Eigen::Isometry3d& T_board_base,
                                        const Eigen::Isometry3d& T_cam_flange) {
  std::vector<PoseResidual> residuals;
  for (const HandEyeObservation& observation : observations) {
    const Eigen::Isometry3d via_board = observation.T_cam_board * T_board_base;
    const Eigen::Isometry3d via_robot = T_cam_flange * observation.T_base_flange.inverse();
    const Eigen::AngleAxisd difference(
        Eigen::Matrix3d(via_board.linear() * via_robot.linear().transpose()));
    residuals.push_back({difference.angle() * 180 / std::numbers::pi,
                         (via_board.translation() - via_robot.translation()).norm() * 1e3});
  }
  return residuals;
}

HandEyeSolution SolveRobotWorldHandEye(const std::vector<HandEyeObservation>& observations,
                                       const DiversityLimits& limits) {
  CheckObservations(observations);
  std::vector<Eigen::Matrix3d> R_A, R_B;
  std::vector<Eigen::Vector3d> t_A, t_B;
  for (const HandEyeObservation& observation : observations) {
    const Eigen::Isometry3d T_flange_base = observation.T_base_flange.inverse();
    R_A.push_back(observation.T_cam_board.linear());
    t_A.push_back(observation.T_cam_board.translation());
    R_B.push_back(T_flange_base.linear());
    t_B.push_back(T_flange_base.translation());
  }
  if (std::string reason = DegeneracyReason(R_B, limits); !reason.empty()) {
    throw DegenerateMotionError("hand-eye calibration refused: " + reason);
  }

  const RotationSolution rotation = SolveRotation(R_A, R_B);
  const TranslationSolution translation = SolveTranslation(R_A, t_A, t_B, rotation.R_Z);
  HandEyeSolution solution;
  solution.T_board_base.linear() = rotation.R_X;
  solution.T_board_base.translation() = translation.t_X;
  solution.T_cam_flange.linear() = rotation.R_Z;
  solution.T_cam_flange.translation() = translation.t_Z;
  solution.residuals = PoseResiduals(observations, solution.T_board_base, solution.T_cam_flange);
  solution.diversity = MeasureMotionDiversity(R_B);
  solution.normalised_singular_values = rotation.normalised_singular_values;
  return solution;
}

}  // namespace avc::calibration::hand_eye
