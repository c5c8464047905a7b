#include "core/kinematics/forward_kinematics.h"

#include <cmath>

namespace avc::kinematics {

Eigen::Isometry3d DhLinkTransform(double a, double d, double alpha, double theta) {
  const double ct = std::cos(theta), st = std::sin(theta);
  const double ca = std::cos(alpha), sa = std::sin(alpha);
  Eigen::Isometry3d link = Eigen::Isometry3d::Identity();
  link.linear() << ct, -st * ca, st * sa,  //
      st, ct * ca, -ct * sa,               //
      0, sa, ca;
  link.translation() << a * ct, a * st, d;
  return link;
}

std::array<Eigen::Isometry3d, 7> JointFrames(const DhParameters& dh, const JointVector& q) {
  std::array<Eigen::Isometry3d, 7> frames;
  frames[0] = Eigen::Isometry3d::Identity();
  for (int i = 0; i < 6; ++i) {
    frames[i + 1] =
        frames[i] * DhLinkTransform(dh.a[i], dh.d[i], dh.alpha[i], q[i] + dh.theta_offset[i]);
  }
  return frames;
}

Eigen::Isometry3d ForwardKinematics(const DhParameters& dh, const JointVector& q) {
  return JointFrames(dh, q)[6];
}

Eigen::Matrix<double, 6, 6> GeometricJacobian(const DhParameters& dh, const JointVector& q) {
  const std::array<Eigen::Isometry3d, 7> frames = JointFrames(dh, q);
  const Eigen::Vector3d flange = frames[6].translation();
  Eigen::Matrix<double, 6, 6> jacobian;
  for (int i = 0; i < 6; ++i) {
    const Eigen::Vector3d axis = frames[i].linear().col(2);
    jacobian.block<3, 1>(0, i) = axis.cross(flange - frames[i].translation());
    jacobian.block<3, 1>(3, i) = axis;
  }
  return jacobian;
}

}  // namespace avc::kinematics
