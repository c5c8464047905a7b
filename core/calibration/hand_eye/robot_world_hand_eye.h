#pragma once

// Robot-world/hand-eye calibration in closed form (Dornaika & Horaud 1998), in the convention of
// OpenCV's calibrateRobotWorldHandEye (T_a_b maps coordinates in frame b to frame a):
//
//   A_i X = Z B_i   with  A_i = T_cam_board,i  (board pose seen by the camera, e.g. solvePnP),
//                         B_i = T_flange_base,i = T_base_flange,i^-1  (robot pose, inverted),
//                         X   = T_board_base  (robot-world),  Z = T_cam_flange  (hand-eye).
//
// Both sides are T_cam_base,i. Callers pass the robot pose as the controller reports it
// (T_base_flange) and get both unknowns in every direction they may need.

#include <Eigen/Geometry>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/calibration/hand_eye/motion_diversity.h"

namespace avc::calibration::hand_eye {

// One calibration pose: the robot's flange pose and the board pose the camera saw there.
struct HandEyeObservation {
  Eigen::Isometry3d T_base_flange = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d T_cam_board = Eigen::Isometry3d::Identity();
};

// A refusal because the poses cannot determine the solution (too few, too little rotation,
// rotations about one axis); what() says which, with the measured figures.
class DegenerateMotionError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

struct PoseResidual {
  double rotation_deg = 0;    // angle between A_i X and Z B_i (two estimates of T_cam_base,i)
  double translation_mm = 0;  // distance between their translations (camera frame)
};

struct HandEyeSolution {
  Eigen::Isometry3d T_board_base = Eigen::Isometry3d::Identity();  // X
  Eigen::Isometry3d T_cam_flange = Eigen::Isometry3d::Identity();  // Z
  std::vector<PoseResidual> residuals;                             // per observation, in order
  MotionDiversity diversity;
  // Singular values of D&H's M over the number of poses (1, ~0, ~0, ~0 for good exact data).
  Eigen::Vector4d normalised_singular_values = Eigen::Vector4d::Zero();

  Eigen::Isometry3d T_base_board() const { return T_board_base.inverse(); }
  Eigen::Isometry3d T_flange_cam() const { return T_cam_flange.inverse(); }
};

// Throws std::invalid_argument naming the observation index for a non-finite or non-rigid pose,
// and DegenerateMotionError when the robot poses fail `limits`.
HandEyeSolution SolveRobotWorldHandEye(const std::vector<HandEyeObservation>& observations,
                                       const DiversityLimits& limits = {});

// Per-observation residuals of a solution (for the closed form or any other estimate).
std::vector<PoseResidual> PoseResiduals(const std::vector<HandEyeObservation>& observations,
                                        const Eigen::Isometry3d& T_board_base,
                                        const Eigen::Isometry3d& T_cam_flange);

// Throws std::invalid_argument naming the index and field of the first bad observation.
void CheckObservations(const std::vector<HandEyeObservation>& observations);

}  // namespace avc::calibration::hand_eye
