#include "core/cell/cell_model.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "core/geometry/rigid_transform.h"
#include "core/kinematics/forward_kinematics.h"

namespace avc::cell {

std::string CellModel::Validate() const {
  if (std::string error = dh.Validate(); !error.empty()) return "robot " + error;
  if (std::string error = geometry::RigidTransformProblem(T_base_table, "T_base_table", 1e-9);
      !error.empty())
    return error;
  if (std::string error = geometry::RigidTransformProblem(T_flange_cam, "T_flange_cam", 1e-9);
      !error.empty())
    return error;
  if (!turntable_axis_table.allFinite() || std::abs(turntable_axis_table.norm() - 1) > 1e-9) {
    return "turntable axis is not a finite unit vector";
  }
  if (!turntable_centre_table.allFinite()) return "turntable centre is not finite";
  if (std::string error = intrinsics.Validate(); !error.empty()) return "camera " + error;
  return {};
}

CellModel NominalCell() {
  CellModel cell;
  cell.dh = kinematics::NominalUr5();
  Eigen::Isometry3d T_table_base = Eigen::Isometry3d::Identity();
  T_table_base.translation() << -0.55, 0.0, 0.2;
  cell.T_base_table = T_table_base.inverse();
  cell.T_flange_cam = Eigen::Isometry3d::Identity();
  cell.T_flange_cam.translation() << 0.0, -0.08, 0.06;
  camera::Intrinsics& k = cell.intrinsics;
  k.width = 1280;
  k.height = 960;
  k.fx = k.fy = 1500;
  k.cx = 639.5;
  k.cy = 479.5;
  k.distortion = {-0.09, 0.11, 2e-4, -1.5e-4, -0.03};
  return cell;
}

Eigen::Isometry3d TableFromWorld(const CellModel& cell, double turntable_angle) {
  const Eigen::Vector3d& centre = cell.turntable_centre_table;
  return Eigen::Translation3d(centre) *
         Eigen::AngleAxisd(turntable_angle, cell.turntable_axis_table) *
         Eigen::Translation3d(-centre);
}

camera::Camera CameraAt(const CellModel& cell, const kinematics::JointVector& q,
                        double turntable_angle) {
  if (std::string error = kinematics::ValidateJoints(q); !error.empty()) {
    throw std::invalid_argument("CameraAt: " + error);
  }
  if (!std::isfinite(turntable_angle)) {
    throw std::invalid_argument("CameraAt: the turntable angle is not finite");
  }
  const Eigen::Isometry3d T_base_flange = kinematics::ForwardKinematics(cell.dh, q);
  camera::Camera camera;
  camera.intrinsics = cell.intrinsics;
  camera.T_cam_world = cell.T_flange_cam.inverse() * T_base_flange.inverse() * cell.T_base_table *
                       TableFromWorld(cell, turntable_angle);
  return camera;
}

}  // namespace avc::cell
