#include "drivers/robot/motion_monitor.h"

#include <fmt/format.h>

#include <cmath>

namespace avc::robot {

std::string_view MotionStatusName(MotionStatus status) {
  switch (status) {
    case MotionStatus::kMoving:
      return "moving";
    case MotionStatus::kReached:
      return "reached";
    case MotionStatus::kSafetyStop:
      return "safety stop";
    case MotionStatus::kNotRunning:
      return "robot not running";
  }
  return "unknown";
}

MotionMonitor MotionMonitor::ForJoints(const std::array<double, 6>& target_q,
                                       const MotionTolerance& tolerance) {
  return MotionMonitor(true, target_q, tolerance);
}

MotionMonitor MotionMonitor::ForPose(const std::array<double, 6>& target_pose,
                                     const MotionTolerance& tolerance) {
  return MotionMonitor(false, target_pose, tolerance);
}

MotionStatus MotionMonitor::Update(const RobotState& state) {
  if (state.safety_mode != SafetyMode::kNormal && state.safety_mode != SafetyMode::kReduced) {
    detail_ =
        fmt::format("stopped by the controller: safety mode {}", SafetyModeName(state.safety_mode));
    return MotionStatus::kSafetyStop;
  }
  if (state.robot_mode != RobotMode::kRunning) {
    detail_ = fmt::format("robot mode is {}, not RUNNING", RobotModeName(state.robot_mode));
    return MotionStatus::kNotRunning;
  }
  double speed = 0;
  for (double qd : state.actual_qd) speed = std::max(speed, std::abs(qd));
  bool within = true;
  if (joint_target_) {
    double error = 0;
    for (size_t i = 0; i < 6; ++i)
      error = std::max(error, std::abs(state.actual_q[i] - target_[i]));
    within = error <= tolerance_.joint_rad;
    detail_ = fmt::format("joint error {:.2e} rad, speed {:.2e} rad/s", error, speed);
  } else {
    const Eigen::Isometry3d actual = PoseFromVector(state.actual_tcp_pose);
    const Eigen::Isometry3d target = PoseFromVector(target_);
    const double position = (actual.translation() - target.translation()).norm();
    const double rotation =
        Eigen::AngleAxisd(Eigen::Matrix3d(actual.linear() * target.linear().transpose())).angle();
    within = position <= tolerance_.position_m && rotation <= tolerance_.rotation_rad;
    detail_ = fmt::format("position error {:.2e} m, rotation error {:.2e} rad, speed {:.2e} rad/s",
                          position, rotation, speed);
  }
  return within && speed <= tolerance_.still_rad_s ? MotionStatus::kReached : MotionStatus::kMoving;
}

}  // namespace avc::robot
