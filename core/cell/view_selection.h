#pragma once

// Choosing arm joints for a view: the camera at a point in the table frame looking at a target,
// image upright, reached by the arm's inverse kinematics on the branch nearest the current joints.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>

#include "core/cell/cell_model.h"
#include "core/kinematics/dh_parameters.h"

namespace avc::cell {

// T_table_cam of a camera at `camera_centre_table` whose optical axis passes through
// `target_table`, with the image's down direction (camera y) as close to the table's -z as
// possible. Looking straight up or down, image down points away from `robot_base_table` (the
// robot then stands at the top of the image). Throws std::invalid_argument for non-finite points
// or a target within 1 micrometre of the centre.
Eigen::Isometry3d LookAtPose(const Eigen::Vector3d& camera_centre_table,
                             const Eigen::Vector3d& target_table,
                             const Eigen::Vector3d& robot_base_table);

// Joints that put the camera of `cell` (its DH set, base placement and hand-eye) at
// `camera_centre_table` looking at `target_table` (LookAtPose), on the inverse-kinematics branch
// nearest to `current` (2 pi turns included, within the joint limits). Pass the nominal cell to
// plan as the drivers do, the calibrated (in the simulator, the true) cell to reach the view
// exactly. nullopt when the arm cannot reach the pose. Throws std::invalid_argument for
// non-finite input or an invalid cell.
std::optional<kinematics::JointVector> JointsLookingAt(const CellModel& cell,
                                                       const Eigen::Vector3d& camera_centre_table,
                                                       const Eigen::Vector3d& target_table,
                                                       const kinematics::JointVector& current);

// Joints that put the camera of `cell` at T_table_cam, on the inverse-kinematics branch nearest to
// `current`; nullopt when the arm cannot reach it. Throws std::invalid_argument like
// JointsLookingAt.
std::optional<kinematics::JointVector> JointsForCameraPose(const CellModel& cell,
                                                           const Eigen::Isometry3d& T_table_cam,
                                                           const kinematics::JointVector& current);

// The point at `distance` from `target` at `elevation` above the table plane and `azimuth`
// (counter-clockwise from the table x axis), all in the table frame, radians and metres.
Eigen::Vector3d ViewpointOnSphere(const Eigen::Vector3d& target, double distance, double elevation,
                                  double azimuth);

// A view of `target` at `elevation` that the arm reaches: tries distances near `distance` and
// azimuths swinging away from `azimuth` (0, +-30, +-60, +-90 degrees), nearest first, and
// returns the first reachable joints (nearest branch to `current`), or nullopt.
struct ReachableView {
  kinematics::JointVector q;
  Eigen::Vector3d centre_table;
};
std::optional<ReachableView> FirstReachableView(const CellModel& cell,
                                                const Eigen::Vector3d& target, double distance,
                                                double elevation, double azimuth,
                                                const kinematics::JointVector& current);

// Azimuth of the robot base's origin seen from the turntable centre in the table frame: views
// within about +-60 degrees of it are the comfortable ones for the arm.
double RobotAzimuth(const CellModel& cell);

// An elbow-up, wrist-down start facing the turntable: inverse kinematics keeps to its branch
// from view to view when each search starts from the joints of the view before.
kinematics::JointVector StartJoints(const CellModel& cell);

}  // namespace avc::cell
