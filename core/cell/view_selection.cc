#include "core/cell/view_selection.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/kinematics/inverse_kinematics.h"

namespace avc::cell {
namespace {

constexpr double kMinimumViewDistance = 1e-6;

}  // namespace

Eigen::Isometry3d LookAtPose(const Eigen::Vector3d& camera_centre_table,
                             const Eigen::Vector3d& target_table,
                             const Eigen::Vector3d& robot_base_table) {
  if (!camera_centre_table.allFinite() || !target_table.allFinite() ||
      !robot_base_table.allFinite()) {
    throw std::invalid_argument("LookAtPose: a point is not finite");
  }
  const Eigen::Vector3d forward = target_table - camera_centre_table;
  if (forward.norm() < kMinimumViewDistance) {
    throw std::invalid_argument("LookAtPose: the target coincides with the camera centre");
  }
  const Eigen::Vector3d z = forward.normalized();
  // x = down x z keeps image down as close to table down as the viewing direction allows.
  Eigen::Vector3d x = (-Eigen::Vector3d::UnitZ()).cross(z);
  if (x.norm() < 1e-9) {
    // Vertical view: image down points horizontally away from the robot.
    Eigen::Vector3d away = camera_centre_table - robot_base_table;
    away.z() = 0;
    if (away.norm() < 1e-9) away = Eigen::Vector3d::UnitX();
    x = away.normalized().cross(z);
  }
  x.normalize();
  const Eigen::Vector3d y = z.cross(x);
  Eigen::Isometry3d T_table_cam = Eigen::Isometry3d::Identity();
  T_table_cam.linear() << x, y, z;
  T_table_cam.translation() = camera_centre_table;
  return T_table_cam;
}

std::optional<kinematics::JointVector> JointsLookingAt(const CellModel& cell,
                                                       const Eigen::Vector3d& camera_centre_table,
                                                       const Eigen::Vector3d& target_table,
                                                       const kinematics::JointVector& current) {
  return JointsForCameraPose(
      cell,
      LookAtPose(camera_centre_table, target_table, cell.T_base_table.inverse().translation()),
      current);
}

std::optional<kinematics::JointVector> JointsForCameraPose(const CellModel& cell,
                                                           const Eigen::Isometry3d& T_table_cam,
                                                           const kinematics::JointVector& current) {
  if (std::string error = cell.Validate(); !error.empty()) {
    throw std::invalid_argument("camera pose to joints: invalid cell: " + error);
  }
  if (!current.allFinite() || !T_table_cam.matrix().allFinite()) {
    throw std::invalid_argument(
        "camera pose to joints: the current joints or the pose are not finite");
  }
  const Eigen::Isometry3d T_base_flange =
      cell.T_base_table * T_table_cam * cell.T_flange_cam.inverse();
  // At a wrist singularity joint 6 is free: keep it where it is.
  const std::vector<kinematics::JointVector> solutions = kinematics::InverseKinematicsRefined(
      cell.dh, T_base_flange, kinematics::WrapAngle(current[5]));
  return kinematics::ClosestSolution(solutions, current);
}

Eigen::Vector3d ViewpointOnSphere(const Eigen::Vector3d& target, double distance, double elevation,
                                  double azimuth) {
  return target + distance * Eigen::Vector3d(std::cos(elevation) * std::cos(azimuth),
                                             std::cos(elevation) * std::sin(azimuth),
                                             std::sin(elevation));
}

std::optional<ReachableView> FirstReachableView(const CellModel& cell,
                                                const Eigen::Vector3d& target, double distance,
                                                double elevation, double azimuth,
                                                const kinematics::JointVector& current) {
  constexpr double kDeg = std::numbers::pi / 180;
  for (const double scale : {1.0, 0.9, 1.1, 0.8, 1.2}) {
    for (const double swing : {0.0, 30.0, -30.0, 60.0, -60.0, 90.0, -90.0}) {
      const Eigen::Vector3d centre =
          ViewpointOnSphere(target, scale * distance, elevation, azimuth + swing * kDeg);
      if (const auto q = JointsLookingAt(cell, centre, target, current)) {
        return ReachableView{*q, centre};
      }
    }
  }
  return std::nullopt;
}

double RobotAzimuth(const CellModel& cell) {
  const Eigen::Vector3d base =
      cell.T_base_table.inverse().translation() - cell.turntable_centre_table;
  return std::atan2(base.y(), base.x());
}

kinematics::JointVector StartJoints(const CellModel& cell) {
  kinematics::JointVector q;
  q << RobotAzimuth(cell), -1.2, 1.6, -1.9, -1.5708, 0;
  return q;
}

}  // namespace avc::cell
