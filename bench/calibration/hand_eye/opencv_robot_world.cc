#include "bench/calibration/hand_eye/opencv_robot_world.h"

#include <opencv2/calib3d.hpp>
#include <stdexcept>

#include "core/geometry/pose_mean.h"

namespace avc::bench {
namespace {

cv::Mat RotationMat(const Eigen::Isometry3d& pose) {
  cv::Mat rotation(3, 3, CV_64F);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) rotation.at<double>(r, c) = pose.linear()(r, c);
  }
  return rotation;
}

cv::Mat TranslationMat(const Eigen::Isometry3d& pose) {
  return (cv::Mat_<double>(3, 1) << pose.translation().x(), pose.translation().y(),
          pose.translation().z());
}

Eigen::Isometry3d Pose(const cv::Mat& rotation, const cv::Mat& translation) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) pose.linear()(r, c) = rotation.at<double>(r, c);
    pose.translation()(r) = translation.at<double>(r);
  }
  return pose;
}

}  // namespace

RobotWorldEstimate SolveWithOpenCvShah(
    const std::vector<calibration::hand_eye::HandEyeObservation>& observations) {
  return SolveWithOpenCvRobotWorld(observations, cv::CALIB_ROBOT_WORLD_HAND_EYE_SHAH);
}

RobotWorldEstimate SolveWithOpenCvRobotWorld(
    const std::vector<calibration::hand_eye::HandEyeObservation>& observations, int method) {
  if (observations.size() < 3) {
    throw std::invalid_argument("calibrateRobotWorldHandEye: OpenCV needs at least 3 observations");
  }
  std::vector<cv::Mat> R_world2cam, t_world2cam, R_base2gripper, t_base2gripper;
  for (const auto& observation : observations) {
    const Eigen::Isometry3d T_flange_base = observation.T_base_flange.inverse();
    R_world2cam.push_back(RotationMat(observation.T_cam_board));
    t_world2cam.push_back(TranslationMat(observation.T_cam_board));
    R_base2gripper.push_back(RotationMat(T_flange_base));
    t_base2gripper.push_back(TranslationMat(T_flange_base));
  }
  cv::Mat R_base2world, t_base2world, R_gripper2cam, t_gripper2cam;
  cv::calibrateRobotWorldHandEye(R_world2cam, t_world2cam, R_base2gripper, t_base2gripper,
                                 R_base2world, t_base2world, R_gripper2cam, t_gripper2cam,
                                 static_cast<cv::RobotWorldHandEyeCalibrationMethod>(method));
  return {Pose(R_base2world, t_base2world), Pose(R_gripper2cam, t_gripper2cam)};
}

RobotWorldEstimate SolveWithOpenCvHandEye(
    const std::vector<calibration::hand_eye::HandEyeObservation>& observations, int method) {
  if (observations.size() < 3) {
    throw std::invalid_argument("calibrateHandEye: OpenCV needs at least 3 observations");
  }
  std::vector<cv::Mat> R_gripper2base, t_gripper2base, R_target2cam, t_target2cam;
  for (const auto& observation : observations) {
    R_gripper2base.push_back(RotationMat(observation.T_base_flange));
    t_gripper2base.push_back(TranslationMat(observation.T_base_flange));
    R_target2cam.push_back(RotationMat(observation.T_cam_board));
    t_target2cam.push_back(TranslationMat(observation.T_cam_board));
  }
  cv::Mat R_cam2gripper, t_cam2gripper;
  cv::calibrateHandEye(R_gripper2base, t_gripper2base, R_target2cam, t_target2cam, R_cam2gripper,
                       t_cam2gripper, static_cast<cv::HandEyeCalibrationMethod>(method));
  const Eigen::Isometry3d T_flange_cam = Pose(R_cam2gripper, t_cam2gripper);
  std::vector<Eigen::Isometry3d> T_base_board;
  for (const auto& observation : observations) {
    T_base_board.push_back(observation.T_base_flange * T_flange_cam * observation.T_cam_board);
  }
  return {geometry::PoseMean(T_base_board).inverse(), T_flange_cam.inverse()};
}

}  // namespace avc::bench
