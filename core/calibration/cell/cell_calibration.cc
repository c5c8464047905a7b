#include "core/calibration/cell/cell_calibration.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "core/geometry/rigid_transform.h"
#include "core/kinematics/forward_kinematics.h"

namespace avc::calibration {
namespace {}  // namespace

std::string CellCalibration::Validate() const {
  if (std::string problem = intrinsics.Validate(); !problem.empty())
    return "intrinsics: " + problem;
  for (const auto& [pose, name] :
       {std::pair{&T_flange_cam, "T_flange_cam"}, std::pair{&T_base_table, "T_base_table"},
        std::pair{&T_table_board, "T_table_board"}}) {
    if (auto problem = geometry::RigidTransformProblem(*pose, name); !problem.empty()) {
      return problem;
    }
  }
  if (std::string problem = dh.Validate(); !problem.empty()) return "kinematics: " + problem;
  return "";
}

Eigen::Isometry3d TableFromWorld(double table_angle) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(table_angle, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return pose;
}

camera::Camera CellCalibration::CameraAt(const Eigen::Isometry3d& T_base_flange,
                                         double table_angle) const {
  if (!T_base_flange.matrix().allFinite() || !std::isfinite(table_angle)) {
    throw std::invalid_argument(
        fmt::format("camera pose query: non-finite flange pose or table angle {}", table_angle));
  }
  camera::Camera camera;
  camera.intrinsics = intrinsics;
  camera.T_cam_world =
      T_flange_cam.inverse() * T_base_flange.inverse() * T_base_table * TableFromWorld(table_angle);
  return camera;
}

camera::Camera CellCalibration::CameraAtJoints(const kinematics::JointVector& q,
                                               double table_angle) const {
  if (std::string problem = kinematics::ValidateJoints(q); !problem.empty()) {
    throw std::invalid_argument("camera pose query: " + problem);
  }
  return CameraAt(kinematics::ForwardKinematics(dh, q), table_angle);
}

}  // namespace avc::calibration
