#include "drivers/robot/motion_wait.h"

#include <fmt/format.h>

namespace avc::robot {

MotionOutcome WaitForMotion(RtdeClient& client, MotionMonitor& monitor, net::Milliseconds timeout,
                            int settle_samples) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  MotionOutcome outcome;
  int reached_in_a_row = 0;
  while (true) {
    const auto left =
        std::chrono::duration_cast<net::Milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) break;
    const auto sample = client.Receive(left);
    if (!sample) break;
    outcome.last_state = sample->state;
    const MotionStatus status = monitor.Update(sample->state);
    outcome.detail = monitor.detail();
    if (status == MotionStatus::kSafetyStop || status == MotionStatus::kNotRunning) {
      outcome.status = status;
      return outcome;
    }
    reached_in_a_row = status == MotionStatus::kReached ? reached_in_a_row + 1 : 0;
    if (reached_in_a_row >= settle_samples) {
      outcome.status = MotionStatus::kReached;
      return outcome;
    }
  }
  outcome.status = MotionStatus::kMoving;
  outcome.detail =
      fmt::format("motion not finished within {} ms: {}", timeout.count(), outcome.detail);
  return outcome;
}

}  // namespace avc::robot
