#pragma once

// Forward kinematics of a standard-DH arm: the flange pose and every joint frame in `base`.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>

#include "core/kinematics/dh_parameters.h"

namespace avc::kinematics {

// T_{i-1,i} = Rz(theta) * Tz(d) * Tx(a) * Rx(alpha).
Eigen::Isometry3d DhLinkTransform(double a, double d, double alpha, double theta);

// T_base_frame_i for i = 0..6: frame 0 is the base (identity), frame 6 the flange. Frame i-1's
// z axis is joint i's rotation axis.
std::array<Eigen::Isometry3d, 7> JointFrames(const DhParameters& dh, const JointVector& q);

// T_base_flange.
Eigen::Isometry3d ForwardKinematics(const DhParameters& dh, const JointVector& q);

// Geometric Jacobian in `base`: rows 0-2 map joint rates to the flange origin's linear velocity,
// rows 3-5 to the flange's angular velocity.
Eigen::Matrix<double, 6, 6> GeometricJacobian(const DhParameters& dh, const JointVector& q);

}  // namespace avc::kinematics
