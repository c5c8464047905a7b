#pragma once

// Follows the RTDE state stream until a commanded motion ends: reached, stopped by the
// controller, or out of time. Never retries: what to do after a stop is the caller's choice.

#include <string>

#include "drivers/robot/motion_monitor.h"
#include "drivers/robot/rtde_client.h"

namespace avc::robot {

struct MotionOutcome {
  MotionStatus status = MotionStatus::kMoving;  // kMoving here means the wait timed out
  std::string detail;
  RobotState last_state;
  bool timed_out() const { return status == MotionStatus::kMoving; }
};

// Reads states until `monitor` says the motion is over or `timeout` passes. `settle_samples`
// consecutive "reached" states are required so a state from before the program started (already
// at the target by chance) or a single noisy sample cannot end the wait early. Throws
// net::ConnectionError when the stream drops.
MotionOutcome WaitForMotion(RtdeClient& client, MotionMonitor& monitor, net::Milliseconds timeout,
                            int settle_samples = 3);

}  // namespace avc::robot
