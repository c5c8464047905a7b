#pragma once

// A ViSP hand-eye dataset (apps/calibration/hand-eye; ../shared/data/handeye_visp): the camera
// (<robot>_camera.xml), the robot poses <robot>_pose_rPe_<i>.yaml (base <- end effector: tx ty tz
// in metres, then a rotation vector), the images <robot>_image-<i>.png of one AprilTag 36h11, and
// apriltag-data.txt with the tag's side ("size: 0.048 m").
// For the eye-to-hand set (a fixed camera, the tag on the flange) the roles of our AX = ZB swap:
// EyeToHandObservations gives the solver the inverted robot poses in the T_base_flange slot, so
// its T_cam_flange is T_cam_base and its T_board_base is T_tag_flange (robot_world_hand_eye.h).

#include <Eigen/Geometry>
#include <filesystem>
#include <string>
#include <vector>

#include "core/calibration/board/tag_detection.h"
#include "core/calibration/hand_eye/reprojection_refinement.h"
#include "core/calibration/hand_eye/robot_world_hand_eye.h"
#include "core/camera/pinhole_camera.h"

namespace avc::bench {

struct VispShot {
  std::string image;                                                // file name
  Eigen::Isometry3d T_base_flange = Eigen::Isometry3d::Identity();  // as the robot reported it
  calibration::TagPose tag;
};

struct VispHandEyeSet {
  camera::Intrinsics intrinsics;
  double tag_size = 0;  // m
  int tag_id = 0;
  std::vector<VispShot> shots;  // in file order 1, 2, ...
};

// Throws std::runtime_error naming the file and what is wrong.
Eigen::Isometry3d ReadVispRobotPose(const std::filesystem::path& path);

// Reads every numbered pose and image of `robot` ("franka") and finds tag `tag_id` in each.
// Throws std::runtime_error naming the file: missing camera, pose or tag-size file, a pose
// without its image, a tag not seen.
VispHandEyeSet ReadVispHandEyeSet(const std::filesystem::path& folder, const std::string& robot,
                                  int tag_id);

// The shots as our solver's observations and board views for a fixed camera (see above).
std::vector<calibration::hand_eye::HandEyeObservation> EyeToHandObservations(
    const VispHandEyeSet& set);
std::vector<calibration::hand_eye::BoardView> EyeToHandBoardViews(const VispHandEyeSet& set);

}  // namespace avc::bench
