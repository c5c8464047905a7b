#pragma once

// A model of the cell: the arm's kinematics, where the robot stands on the table, the turntable's
// axis, the hand-eye transform and the camera's intrinsics. The planner plans with the model a
// calibration gives (services/planner/calibrated_cell.h), the calibrator with the nominal one;
// the simulator's truth (sim::CellTruth) is a model whose values it chose and hides from the
// drivers and the calibrator, which must recover them.
//
// Frames (T_a_b maps coordinates in frame b to frame a): table is fixed, z up, origin at the centre
// of the turntable top; world is the plant frame riding on the turntable, equal to table at
// turntable angle 0; base is the UR controller's base frame; flange the tool flange; cam the OpenCV
// camera frame.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>

#include "core/camera/pinhole_camera.h"
#include "core/kinematics/dh_parameters.h"

namespace avc::cell {

struct CellModel {
  kinematics::DhParameters dh;  // the arm's DH set
  Eigen::Isometry3d T_base_table = Eigen::Isometry3d::Identity();
  // The turntable turns about the line through `turntable_centre_table` along the unit
  // `turntable_axis_table` (both in the table frame, metres); positive angles turn
  // counter-clockwise seen from above (right-handed about the axis).
  Eigen::Vector3d turntable_axis_table = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d turntable_centre_table = Eigen::Vector3d::Zero();
  Eigen::Isometry3d T_flange_cam = Eigen::Isometry3d::Identity();
  camera::Intrinsics intrinsics;

  // Empty when usable, else a sentence naming the bad field.
  std::string Validate() const;
};

// A sensible cell: a nominal UR5 on a pedestal, its base 0.55 m from the turntable axis and
// 0.2 m above the turntable top (looking down on the plant reaches the high elevations), a
// 1280x960 Canon-like camera (fx = fy = 1500 px, mild barrel distortion) 6 cm in front of and
// 8 cm beside the flange, looking along the flange axis. The field of view is 0.85 x 0.64 times
// the distance: a 0.3 m plant spans the image width at 0.35 m and its height at 0.47 m, and
// half the height at 0.8 m.
CellModel NominalCell();

// T_table_world at `turntable_angle` (radians): the rotation by that angle about the axis.
Eigen::Isometry3d TableFromWorld(const CellModel& cell, double turntable_angle);

// The camera with the arm at joints `q` (through the cell's DH set) and the turntable at
// `turntable_angle`: T_cam_world = T_cam_flange * T_flange_base(q) * T_base_table *
// T_table_world(angle). Throws std::invalid_argument for non-finite joints or angle.
camera::Camera CameraAt(const CellModel& cell, const kinematics::JointVector& q,
                        double turntable_angle);

}  // namespace avc::cell
