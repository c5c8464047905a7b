#pragma once

// Joint refinement of robot-world and hand-eye (X = T_board_base, Z = T_cam_flange) on the
// checkerboard reprojection error of every corner in every view (as Tabb & Ahmad Yousef 2017):
// corner P_k of view i images at pi(K, dist, Z * T_base_flange,i^-1 * X^-1 * P_k). Intrinsics are
// fixed; rotations live on Ceres' EigenQuaternionManifold. Starting point: the closed form.
//
// The reported robot poses are not exact either. Taking them as exact lets their small errors
// steer the solution along the directions a narrow-angle camera measures poorly (a camera that
// orbits the board barely changes its image), which made the plain reprojection fit 8x worse than
// the closed form with robot noise alone (hand-eye 0.041 vs 0.005 deg median, 1280x960 camera;
// 0.018 deg with the corrections below) and no better than it on BENCHMARKS.md's 650D-like 18 MP
// setup (0.040 vs 0.035 deg; 0.019 deg with corrections). So each view also
// gets a small correction of its robot pose (rotation vector and translation in `base`,
// T_base_flange,true = [Exp(w) R | t + tau]) held by a Gaussian prior of the robot's noise: the
// cost is the negative log-likelihood of pixels and robot poses together, scaled to pixels^2.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "core/camera/pinhole_camera.h"

namespace avc::calibration::hand_eye {

// One calibration view: the robot pose and the board corners found in the image.
struct BoardView {
  Eigen::Isometry3d T_base_flange = Eigen::Isometry3d::Identity();
  std::vector<Eigen::Vector3d> board_points;  // corners in the board frame (metres)
  std::vector<Eigen::Vector2d> pixels;        // their detections, same order (pixels)
};

struct RefinementOptions {
  // Huber loss scale in pixels (a corner off by more counts linearly, limiting the pull of a
  // misdetected corner); 0 = plain least squares.
  double huber_px = 1.0;
  // Noise of the corner detections (per pixel axis) and of the reported robot pose (per axis of
  // its rotation vector and translation): they weigh pixels against robot-pose corrections. The
  // defaults are a sub-pixel checkerboard detector and a UR5-class arm. Both robot sigmas 0 =
  // robot poses taken as exact (no corrections).
  double pixel_sigma_px = 0.5;
  double robot_rotation_sigma_deg = 0.005;
  double robot_translation_sigma_mm = 0.05;
  int max_iterations = 100;
};

struct RefinementResult {
  Eigen::Isometry3d T_board_base = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d T_cam_flange = Eigen::Isometry3d::Identity();
  // Root mean square of the corners' pixel distances (not squared-loss weighted), per view and
  // over all corners, before (at the start) and after refinement, through the robot poses as
  // reported (as the calibrated chain will be used at run time).
  std::vector<double> view_rms_px;
  double rms_px = 0;
  double initial_rms_px = 0;
  // The fitted robot-pose corrections per view (rotation deg, translation mm); a view far
  // beyond the robot's noise is suspect. Zero when corrections are off.
  std::vector<double> view_robot_correction_deg;
  std::vector<double> view_robot_correction_mm;
  int iterations = 0;
  bool converged = false;
  std::string solver_report;  // Ceres' one-line summary
};

// Throws std::invalid_argument for invalid intrinsics or options, no views, a view whose points
// and pixels differ in number or are empty or not finite, a non-rigid pose (naming the view), or
// a corner behind the camera at the start; std::runtime_error when Ceres fails outright.
RefinementResult RefineOnReprojection(const std::vector<BoardView>& views,
                                      const camera::Intrinsics& intrinsics,
                                      const Eigen::Isometry3d& T_board_base_start,
                                      const Eigen::Isometry3d& T_cam_flange_start,
                                      const RefinementOptions& options = {});

// Per-view RMS pixel distance of the views' corners under the given transforms (corners behind
// the camera count as infinitely far).
std::vector<double> ViewReprojectionRms(const std::vector<BoardView>& views,
                                        const camera::Intrinsics& intrinsics,
                                        const Eigen::Isometry3d& T_board_base,
                                        const Eigen::Isometry3d& T_cam_flange);

}  // namespace avc::calibration::hand_eye
