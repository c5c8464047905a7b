#pragma once

// Synthetic robot-world/hand-eye data like the real cell's (as in BENCHMARKS.md): a 9x6-corner,
// 25 mm checkerboard lying on the turntable; the arm of a perturbed sim cell (true hand-eye and
// base placement differ per seed) puts the camera 0.4-0.8 m from it, looking down from 30-75 deg
// elevation within +-60 deg of the robot's side, rolled +-30 deg about the optical axis. Every
// pose is reachable by the nominal UR5 and sees every corner. Noise: Gaussian corner pixels,
// then solvePnP for the board pose; Gaussian robot pose (rotation vector and translation per
// axis). Bit-identical for a seed on any standard library (own Box-Muller on mt19937_64 bits).

#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/calibration/hand_eye/reprojection_refinement.h"
#include "core/calibration/hand_eye/robot_world_hand_eye.h"
#include "core/camera/pinhole_camera.h"

namespace avc::bench {

struct HandEyeScenarioOptions {
  // The camera, taken as already calibrated; nullopt = sim::NominalCell()'s.
  std::optional<camera::Intrinsics> intrinsics;
  int poses = 10;
  double pixel_sigma_px = 0;
  double robot_rotation_sigma_deg = 0;
  double robot_translation_sigma_mm = 0;
  int board_columns = 9;  // inner corners
  int board_rows = 6;
  double square_m = 0.025;
  double min_distance_m = 0.4;
  double max_distance_m = 0.8;
  double min_elevation_deg = 30;
  double max_elevation_deg = 75;
  double azimuth_half_range_deg = 60;  // about the robot's azimuth seen from the table centre
  double roll_half_range_deg = 30;

  // Empty when usable; else a sentence naming the bad option.
  std::string Validate() const;
};

struct HandEyeSyntheticView {
  Eigen::Isometry3d true_T_base_flange;
  Eigen::Isometry3d T_base_flange;  // as the robot reports it (with robot noise)
  Eigen::Isometry3d true_T_cam_board;
  Eigen::Isometry3d T_cam_board;        // solvePnP on the noisy corners
  std::vector<Eigen::Vector2d> pixels;  // noisy corner detections
};

struct HandEyeScenario {
  camera::Intrinsics intrinsics;
  Eigen::Isometry3d true_T_flange_cam;
  Eigen::Isometry3d true_T_base_board;
  std::vector<Eigen::Vector3d> board_points;  // board frame, row by row
  std::vector<HandEyeSyntheticView> views;

  // What a calibrator sees: reported robot poses and PnP board poses.
  std::vector<calibration::hand_eye::HandEyeObservation> Observations() const;
  // The exact poses (no noise, no PnP).
  std::vector<calibration::hand_eye::HandEyeObservation> TrueObservations() const;
  // Reported robot poses with the noisy corners, for the reprojection refinement.
  std::vector<calibration::hand_eye::BoardView> BoardViews() const;
};

// Throws std::invalid_argument for options that cannot give a scenario (fewer than 1 pose,
// non-positive sizes, negative noise, empty ranges) and std::runtime_error when no reachable,
// fully visible pose is found in many attempts.
HandEyeScenario MakeHandEyeScenario(const HandEyeScenarioOptions& options, uint64_t seed);

}  // namespace avc::bench
