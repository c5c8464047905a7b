#pragma once

// How far apart two rigid poses are: translation distance and geodesic rotation angle.

#include <Eigen/Geometry>

namespace avc::kinematics {

struct PoseDifference {
  double translation_m = 0;
  double rotation_rad = 0;
};

inline PoseDifference ComparePoses(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  const Eigen::AngleAxisd relative(Eigen::Matrix3d(a.linear() * b.linear().transpose()));
  return {(a.translation() - b.translation()).norm(), relative.angle()};
}

}  // namespace avc::kinematics
