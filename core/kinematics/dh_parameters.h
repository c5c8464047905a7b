#pragma once

// Standard Denavit–Hartenberg description of a six-joint serial arm, as Universal Robots
// publishes it: T_{i-1,i} = Rz(theta_i) * Tz(d_i) * Tx(a_i) * Rx(alpha_i), with
// theta_i = q_i + theta_offset_i. Frame 0 is the controller's `base` frame (not ROS
// `base_link`), frame 6 the tool flange (z out of the flange).

#include <Eigen/Core>
#include <numbers>
#include <string>

namespace avc::kinematics {

using JointVector = Eigen::Matrix<double, 6, 1>;

// Every UR joint turns +-2 pi (two full turns end to end).
inline constexpr double kJointLimitRad = 2 * std::numbers::pi;

struct DhParameters {
  JointVector a = JointVector::Zero();             // metres, along x_i
  JointVector d = JointVector::Zero();             // metres, along z_{i-1}
  JointVector alpha = JointVector::Zero();         // radians, about x_i
  JointVector theta_offset = JointVector::Zero();  // radians, added to the joint reading

  // Empty when usable, else a sentence naming the bad entry.
  std::string Validate() const;
};

// The UR5 CB3 ("series 3") nominal parameters (UR's published table, also ur_kin.cpp UR5_PARAMS).
DhParameters NominalUr5();

// Angle wrapped to (-pi, pi].
double WrapAngle(double angle);
JointVector WrapJoints(const JointVector& q);

bool WithinJointLimits(const JointVector& q);

// Empty when every entry is finite and within the joint limits, else a sentence naming the joint.
std::string ValidateJoints(const JointVector& q);

}  // namespace avc::kinematics
