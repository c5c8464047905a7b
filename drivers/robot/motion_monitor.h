#pragma once

// Decides from RTDE state when a commanded motion has finished: the target is reached within
// tolerance and the joints are still, or the controller stopped it (protective stop or another
// safety stop). A stop is reported as such, never retried: recovering is the caller's decision.

#include <Eigen/Geometry>
#include <array>
#include <string>

#include "drivers/robot/protocol/ur_pose.h"
#include "drivers/robot/robot_state.h"

namespace avc::robot {

struct MotionTolerance {
  double joint_rad = 1e-3;
  double position_m = 1e-3;
  double rotation_rad = 2e-3;
  double still_rad_s = 2e-3;  // every |actual_qd| below this counts as stopped
};

enum class MotionStatus { kMoving, kReached, kSafetyStop, kNotRunning };

std::string_view MotionStatusName(MotionStatus status);

class MotionMonitor {
 public:
  static MotionMonitor ForJoints(const std::array<double, 6>& target_q,
                                 const MotionTolerance& tolerance = {});
  static MotionMonitor ForPose(const std::array<double, 6>& target_pose,
                               const MotionTolerance& tolerance = {});

  // The motion's status given the newest state; `detail` explains stops and remaining error.
  MotionStatus Update(const RobotState& state);
  const std::string& detail() const { return detail_; }

 private:
  MotionMonitor(bool joint_target, const std::array<double, 6>& target,
                const MotionTolerance& tolerance)
      : joint_target_(joint_target), target_(target), tolerance_(tolerance) {}

  bool joint_target_;
  std::array<double, 6> target_;
  MotionTolerance tolerance_;
  std::string detail_;
};

}  // namespace avc::robot
