#include "core/dataset/world_up.h"

#include <Eigen/Geometry>

namespace avc::dataset {

namespace {

// The mean of the cameras' image-up directions (-y of each camera) in world coordinates.
Eigen::Vector3d MeanImageUp(const std::vector<camera::Camera>& cameras) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const camera::Camera& camera : cameras) {
    sum -= camera.T_cam_world.linear().row(1).transpose();  // minus the second row of R
  }
  return cameras.empty() ? sum : Eigen::Vector3d(sum / static_cast<double>(cameras.size()));
}

}  // namespace

bool CamerasAgreeZIsUp(const std::vector<camera::Camera>& cameras) {
  return MeanImageUp(cameras).z() >= kMinUpAgreement;
}

std::optional<UprightTurn> FindUprightTurn(const std::vector<camera::Camera>& cameras) {
  const Eigen::Vector3d mean = MeanImageUp(cameras);
  if (mean.norm() < kMinUpAgreement) return std::nullopt;
  Eigen::Index axis = 0;
  mean.cwiseAbs().maxCoeff(&axis);
  const double sign = mean[axis] > 0 ? 1.0 : -1.0;
  if (axis == 2 && sign > 0) return std::nullopt;
  Eigen::Vector3d up = Eigen::Vector3d::Zero();
  up[axis] = sign;
  // The turn taking `up` to +z: about x for a y axis, about y for an x axis, half a turn about x
  // for -z. Every entry is 0 or +-1.
  UprightTurn turn;
  if (axis == 2) {
    turn.rotation = Eigen::Vector3d(1, -1, -1).asDiagonal();
  } else {
    const Eigen::Vector3d rotation_axis = up.cross(Eigen::Vector3d::UnitZ());
    turn.rotation = Eigen::AngleAxisd(M_PI / 2, rotation_axis).toRotationMatrix();
    turn.rotation = turn.rotation.array().round().matrix();
  }
  turn.from_axis = std::string(sign > 0 ? "+" : "-") + "xyz"[axis];
  return turn;
}

}  // namespace avc::dataset
