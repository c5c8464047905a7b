#pragma once

// Hand-eye methods compared on one data set (`avc bench calibration`): our AX = ZB code as
// `avc calibrate solve` runs it (the closed form and the refinements; the one that best predicts
// a left-out pose is written) and OpenCV's five calibrateHandEye and two
// calibrateRobotWorldHandEye methods on the same detections. Per method: the leave-one-out error
// (fit without a pose, predict the board's pose in the camera there; median over the poses, as
// hand_eye_choice.h measures it) and the spread of the fixed frame's pose (the board in the base,
// or for a fixed camera the tag in the flange) computed from each shot through the solution.
// Run on the simulated cell's detections and on the shared ViSP eye-to-hand set (a Franka arm
// holding an AprilTag before a fixed camera, 8 poses).

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/calibration/hand_eye/motion_diversity.h"
#include "core/calibration/hand_eye/reprojection_refinement.h"
#include "core/calibration/hand_eye/robot_world_hand_eye.h"
#include "core/camera/pinhole_camera.h"

namespace avc::bench {

// Every method on one hand-eye data set: ours through ChooseHandEye with `diversity` and
// `refinement` (the one it writes marked "written"), OpenCV's on the same observations.
nlohmann::json CompareHandEyeMethods(
    const std::vector<calibration::hand_eye::HandEyeObservation>& observations,
    const std::vector<calibration::hand_eye::BoardView>& board_views,
    const camera::Intrinsics& intrinsics, const calibration::hand_eye::DiversityLimits& diversity,
    const calibration::hand_eye::RefinementOptions& refinement);
std::string FormatHandEyeComparison(const nlohmann::json& comparison, const std::string& title);

// Throws std::runtime_error naming the file when the set cannot be read.
nlohmann::json RunRealEyeToHand(const std::filesystem::path& folder);
std::string FormatRealEyeToHand(const nlohmann::json& result);

}  // namespace avc::bench
