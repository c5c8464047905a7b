#include "drivers/robot/protocol/ur_pose.h"

namespace avc::robot {

Eigen::Matrix3d RotationFromVector(const Eigen::Vector3d& rotation_vector) {
  const double angle = rotation_vector.norm();
  if (angle < 1e-15) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, rotation_vector / angle).toRotationMatrix();
}

Eigen::Isometry3d PoseFromVector(const std::array<double, 6>& pose) {
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();
  transform.translation() = Eigen::Vector3d(pose[0], pose[1], pose[2]);
  transform.linear() = RotationFromVector(Eigen::Vector3d(pose[3], pose[4], pose[5]));
  return transform;
}

std::array<double, 6> VectorFromPose(const Eigen::Isometry3d& pose) {
  const Eigen::AngleAxisd angle_axis(Eigen::Matrix3d(pose.linear()));
  const Eigen::Vector3d rotation = angle_axis.axis() * angle_axis.angle();
  const Eigen::Vector3d position = pose.translation();
  return {position.x(), position.y(), position.z(), rotation.x(), rotation.y(), rotation.z()};
}

}  // namespace avc::robot
