#pragma once

// The emulated arm's motion: movej as one trapezoidal profile along the straight joint-space line
// (every joint arrives together, the largest move sets the time), movel as a trapezoid along the
// straight tool line with slerped orientation, tracked by Newton IK on the arm's TRUE DH set,
// stopj as constant deceleration along the current path. Pure and stepped: no clock, no threads.

#include <Eigen/Geometry>
#include <string>

#include "core/kinematics/dh_parameters.h"
#include "sim/emulators/ur5/trapezoid_profile.h"

namespace avc::sim::ur5 {

using kinematics::JointVector;

class Ur5Arm {
 public:
  Ur5Arm(const kinematics::DhParameters& dh, const JointVector& q);

  // Each returns an empty string when the motion started, else the runtime error the controller
  // would raise (bad numbers, joint limits, unreachable target).
  std::string StartMoveJ(const JointVector& target, double acceleration, double velocity);
  std::string StartMoveJToPose(const Eigen::Isometry3d& T_base_flange, double acceleration,
                               double velocity);
  std::string StartMoveL(const Eigen::Isometry3d& T_base_flange, double acceleration,
                         double velocity);
  // Decelerates along the current path at `deceleration` (joint rad/s^2 for movej, m/s^2 for
  // movel) until still.
  void Brake(double deceleration);
  // Stops dead (protective stop, power off).
  void Halt();

  // Advances by dt seconds; returns a runtime error when the motion could not continue (movel
  // leaving the workspace), after which the arm is halted.
  std::string Step(double dt);

  bool moving() const { return kind_ != Kind::kNone; }
  // Fraction of the current path covered, 0 when still.
  double progress() const;
  const JointVector& q() const { return q_; }
  const JointVector& qd() const { return qd_; }
  const JointVector& target_q() const { return target_q_; }
  const kinematics::DhParameters& dh() const { return dh_; }

 private:
  enum class Kind { kNone, kJoint, kLinear };
  // Path parameter and its rate at the current time (profile or braking).
  double PathPosition() const;
  double PathVelocity() const;
  std::string StartPath(Kind kind, double length, double acceleration, double velocity);

  kinematics::DhParameters dh_;
  JointVector q_;
  JointVector qd_ = JointVector::Zero();
  JointVector target_q_;
  Kind kind_ = Kind::kNone;
  JointVector start_q_, delta_q_;
  Eigen::Isometry3d start_pose_, end_pose_;
  TrapezoidProfile profile_;
  double time_ = 0;
  bool braking_ = false;
  double brake_start_s_ = 0, brake_start_v_ = 0, brake_decel_ = 1, brake_time_ = 0;
};

}  // namespace avc::sim::ur5
