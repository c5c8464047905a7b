#include "sim/emulators/ur5/ur5_arm.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/kinematics/forward_kinematics.h"
#include "core/kinematics/inverse_kinematics.h"

namespace avc::sim::ur5 {
namespace {

std::string CheckRates(double acceleration, double velocity, const char* what) {
  if (!(std::isfinite(acceleration) && acceleration > 0 && std::isfinite(velocity) &&
        velocity > 0)) {
    return fmt::format("{}: acceleration {} and velocity {} must be positive", what, acceleration,
                       velocity);
  }
  return {};
}

Eigen::Isometry3d Interpolate(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b, double u) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = (1 - u) * a.translation() + u * b.translation();
  pose.linear() = Eigen::Quaterniond(a.linear())
                      .slerp(u, Eigen::Quaterniond(b.linear()))
                      .normalized()
                      .toRotationMatrix();
  return pose;
}

}  // namespace

Ur5Arm::Ur5Arm(const kinematics::DhParameters& dh, const JointVector& q)
    : dh_(dh), q_(q), target_q_(q) {}

std::string Ur5Arm::StartPath(Kind kind, double length, double acceleration, double velocity) {
  kind_ = kind;
  profile_ = TrapezoidProfile(length, velocity, acceleration);
  time_ = 0;
  braking_ = false;
  return {};
}

std::string Ur5Arm::StartMoveJ(const JointVector& target, double acceleration, double velocity) {
  if (auto error = CheckRates(acceleration, velocity, "movej"); !error.empty()) return error;
  if (auto error = kinematics::ValidateJoints(target); !error.empty()) {
    return "movej: " + error;
  }
  start_q_ = q_;
  delta_q_ = target - q_;
  target_q_ = q_;
  const double length = delta_q_.cwiseAbs().maxCoeff();
  if (length == 0) {
    Halt();
    return {};
  }
  return StartPath(Kind::kJoint, length, acceleration, velocity);
}

std::string Ur5Arm::StartMoveJToPose(const Eigen::Isometry3d& T_base_flange, double acceleration,
                                     double velocity) {
  const auto solutions = kinematics::InverseKinematicsRefined(dh_, T_base_flange);
  const auto closest = kinematics::ClosestSolution(solutions, q_);
  if (!closest) return "movej: pose target is out of reach (no inverse kinematics solution)";
  return StartMoveJ(*closest, acceleration, velocity);
}

std::string Ur5Arm::StartMoveL(const Eigen::Isometry3d& T_base_flange, double acceleration,
                               double velocity) {
  if (auto error = CheckRates(acceleration, velocity, "movel"); !error.empty()) return error;
  if (!T_base_flange.matrix().allFinite()) return "movel: target pose is not finite";
  const auto solutions = kinematics::InverseKinematicsRefined(dh_, T_base_flange);
  if (!kinematics::ClosestSolution(solutions, q_)) {
    return "movel: target pose is out of reach (no inverse kinematics solution)";
  }
  start_pose_ = kinematics::ForwardKinematics(dh_, q_);
  end_pose_ = T_base_flange;
  const double translation = (end_pose_.translation() - start_pose_.translation()).norm();
  const double rotation =
      Eigen::AngleAxisd(Eigen::Matrix3d(end_pose_.linear() * start_pose_.linear().transpose()))
          .angle();
  // Like the controller, a pure reorientation is timed by its angle (v, a read as rad/s).
  const double length = translation > 1e-6 ? translation : rotation;
  target_q_ = q_;
  if (length == 0) {
    Halt();
    return {};
  }
  return StartPath(Kind::kLinear, length, acceleration, velocity);
}

double Ur5Arm::PathPosition() const {
  if (!braking_) return profile_.Position(time_);
  const double t = std::min(brake_time_, brake_start_v_ / brake_decel_);
  return std::min(profile_.distance(),
                  brake_start_s_ + brake_start_v_ * t - 0.5 * brake_decel_ * t * t);
}

double Ur5Arm::PathVelocity() const {
  if (!braking_) return profile_.Velocity(time_);
  return std::max(0.0, brake_start_v_ - brake_decel_ * brake_time_);
}

double Ur5Arm::progress() const {
  if (!moving() || profile_.distance() == 0) return 0;
  return PathPosition() / profile_.distance();
}

void Ur5Arm::Brake(double deceleration) {
  if (!moving() || braking_) return;
  // The path parameter of a joint move is the leading joint's angle, so stopj's deceleration
  // applies to it directly; a bad value falls back to a firm 1 unit/s^2.
  const double decel = std::isfinite(deceleration) && deceleration > 0 ? deceleration : 1.0;
  brake_start_s_ = PathPosition();
  brake_start_v_ = PathVelocity();
  brake_decel_ = decel;
  brake_time_ = 0;
  braking_ = true;
}

void Ur5Arm::Halt() {
  kind_ = Kind::kNone;
  braking_ = false;
  qd_.setZero();
  target_q_ = q_;
}

std::string Ur5Arm::Step(double dt) {
  if (!moving()) {
    qd_.setZero();
    return {};
  }
  if (braking_) {
    brake_time_ += dt;
  } else {
    time_ += dt;
  }
  const double s = PathPosition();
  const double length = profile_.distance();
  const double u = std::clamp(s / length, 0.0, 1.0);
  const bool finished = braking_ ? PathVelocity() <= 0 : time_ >= profile_.duration();
  const JointVector previous = q_;
  if (kind_ == Kind::kJoint) {
    q_ = start_q_ + u * delta_q_;
    qd_ = finished ? JointVector::Zero() : JointVector(delta_q_ * (PathVelocity() / length));
  } else {
    const auto next =
        kinematics::RefineInverseKinematics(dh_, Interpolate(start_pose_, end_pose_, u), q_, 1e-10);
    if (!next) {
      Halt();
      return "movel: the straight tool path leaves the workspace (inverse kinematics failed)";
    }
    q_ = *next;
    qd_ = finished ? JointVector::Zero() : JointVector((q_ - previous) / dt);
  }
  target_q_ = q_;
  if (finished) Halt();
  return {};
}

}  // namespace avc::sim::ur5
