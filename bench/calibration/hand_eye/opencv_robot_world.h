#pragma once

// The baseline: OpenCV 4.6's cv::calibrateRobotWorldHandEye with CALIB_ROBOT_WORLD_HAND_EYE_SHAH
// on the same observations. Its convention is ours (robot_world_hand_eye.h): world2cam = A_i =
// T_cam_board, base2gripper = B_i = T_flange_base (the robot pose inverted), and it returns
// base2world = X = T_board_base and gripper2cam = Z = T_cam_flange.

#include <Eigen/Geometry>
#include <vector>

#include "core/calibration/hand_eye/robot_world_hand_eye.h"

namespace avc::bench {

struct RobotWorldEstimate {
  Eigen::Isometry3d T_board_base = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d T_cam_flange = Eigen::Isometry3d::Identity();
};

// Throws std::invalid_argument for fewer than 3 observations (OpenCV's minimum).
RobotWorldEstimate SolveWithOpenCvShah(
    const std::vector<calibration::hand_eye::HandEyeObservation>& observations);

// The same with any of cv::calibrateRobotWorldHandEye's methods (SHAH, LI).
RobotWorldEstimate SolveWithOpenCvRobotWorld(
    const std::vector<calibration::hand_eye::HandEyeObservation>& observations, int method);

// cv::calibrateHandEye (AX = XB: TSAI, PARK, HORAUD, ANDREFF, DANIILIDIS) on the same
// observations: gripper2base = T_base_flange, target2cam = T_cam_board, giving cam2gripper =
// T_flange_cam; the board's pose in the base, which AX = XB leaves out, is then the chordal mean
// over the observations of T_base_flange,i T_flange_cam T_cam_board,i, as a user of that
// function would take it. Throws std::invalid_argument for fewer than 3 observations.
RobotWorldEstimate SolveWithOpenCvHandEye(
    const std::vector<calibration::hand_eye::HandEyeObservation>& observations, int method);

}  // namespace avc::bench
