#include "drivers/robot/heartbeat_watchdog.h"

#include <fmt/format.h>

#include <utility>

namespace avc::robot {

HeartbeatWatchdog::HeartbeatWatchdog(std::string service, Milliseconds timeout,
                                     Milliseconds presence)
    : service_(std::move(service)), timeout_(timeout), presence_(presence) {}

void HeartbeatWatchdog::Heard(TimePoint now, bool healthy, std::string state) {
  last_heard_ = now;
  healthy_ = healthy;
  state_ = std::move(state);
}

bool HeartbeatWatchdog::ShouldWatch(TimePoint now) const {
  return enabled() && last_heard_ && now - *last_heard_ <= presence_;
}

std::string HeartbeatWatchdog::Problem(TimePoint now) const {
  if (!last_heard_) return {};
  const auto silence = std::chrono::duration_cast<Milliseconds>(now - *last_heard_);
  if (silence > timeout_) {
    return fmt::format("{} heartbeat lost for {} ms", service_, silence.count());
  }
  if (!healthy_) return fmt::format("{} reported {}", service_, state_);
  return {};
}

std::string HeartbeatWatchdog::StopReason(TimePoint now) const {
  const std::string problem = Problem(now);
  return problem.empty() ? problem : problem + "; arm stopped";
}

}  // namespace avc::robot
