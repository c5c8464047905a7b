#pragma once

// What one calibration of the cell knows (paper §2.1): the camera's intrinsics, where the camera
// sits on the flange (hand-eye), where the turntable's axis is relative to the robot base, and
// the arm's kinematics. With it the camera pose follows for any arm pose and turntable angle,
// with no target in view:
//
//   T_cam_world(q, theta) = T_cam_flange · T_flange_base(q) · T_base_table · T_table_world(theta)
//
// The table frame (calibration/turntable TableFrame) has z along the turntable axis, pointing so
// that a positive angle turns right-handed about it (counter-clockwise seen from above, as the
// LT360 driver counts), its origin on the axis level with the calibration board, and x towards
// the board's origin at angle 0.
// T_table_world(theta) is the rotation by theta about z; the world (plant) frame equals the table
// frame at angle 0.

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "core/camera/pinhole_camera.h"
#include "core/kinematics/dh_parameters.h"

namespace avc::calibration {

// How well the calibration fits what it was computed from.
struct CalibrationResiduals {
  std::vector<std::string> view_names;
  std::vector<double> view_rms_px;    // reprojection RMS per view used
  std::vector<std::string> rejected;  // views left out, each "name: why"
  double intrinsics_rms_px = 0;       // calibrateCamera's overall RMS
  double hand_eye_rms_px = 0;         // board corners through the refined hand-eye chain
  double hand_eye_rotation_deg = 0;   // AX=ZB residuals (median over poses)
  double hand_eye_translation_mm = 0;
  // Which hand-eye was kept ("refined" or "closed form") and how well each predicts a pose
  // left out of its fit (median; calibration/pipeline/hand_eye_choice.h). Empty method: a file
  // from before the choice.
  std::string hand_eye_method;
  double hand_eye_loo_rotation_deg = 0;
  double hand_eye_loo_translation_mm = 0;
  std::string alternative_method;
  double alternative_rms_px = 0;
  double alternative_loo_rotation_deg = 0;
  double alternative_loo_translation_mm = 0;
  double turntable_centre_rms_mm = 0;  // board points about the fitted axis
  int turntable_angles = 0;
};

struct CellCalibration {
  static constexpr int kFormatVersion = 1;

  camera::Intrinsics intrinsics;
  Eigen::Isometry3d T_flange_cam = Eigen::Isometry3d::Identity();
  // False for a hand-eye-only calibration (no turntable shots): then T_base_table is the board's
  // pose in the base frame (robot-world), which no turntable angle moves, and a scan refuses it.
  bool turntable_calibrated = true;
  Eigen::Isometry3d T_base_table = Eigen::Isometry3d::Identity();
  // Where the calibration board lay at angle 0, in the table (= world) frame: relates this
  // calibration's world frame to the board, e.g. to compare with a simulator's truth.
  Eigen::Isometry3d T_table_board = Eigen::Isometry3d::Identity();
  // The arm's kinematics for joint-vector queries: the controller's own (KINEMATICS_INFO), not
  // the nominal UR5 table, which can be centimetres off.
  kinematics::DhParameters dh = kinematics::NominalUr5();
  CalibrationResiduals residuals;
  std::string note;  // free text: how, when, from what

  // Empty when usable, else the first bad field.
  std::string Validate() const;

  // The camera for a flange pose reported by the controller (actual TCP with TCP = 0).
  camera::Camera CameraAt(const Eigen::Isometry3d& T_base_flange, double table_angle) const;
  // The camera for a joint vector (planning): forward kinematics with `dh`.
  camera::Camera CameraAtJoints(const kinematics::JointVector& q, double table_angle) const;
};

// T_table_world(theta): rotation by theta about the table's z axis.
Eigen::Isometry3d TableFromWorld(double table_angle);

}  // namespace avc::calibration
