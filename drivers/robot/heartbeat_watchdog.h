#pragma once

// Stops the arm when the process commanding it dies: remembers when the watched service (the
// orchestrator) was last heard and in which state, decides at the start of a motion whether it
// is watched (the service was heard recently, so it is the one driving), and during a watched
// motion says when to stop it (heartbeat silent longer than the timeout, or the service says it
// is stopping or in error). Manual use without the service runs unwatched. No bus, no clock of
// its own: the node passes the times in.

#include <chrono>
#include <optional>
#include <string>

namespace avc::robot {

class HeartbeatWatchdog {
 public:
  using TimePoint = std::chrono::steady_clock::time_point;
  using Milliseconds = std::chrono::milliseconds;

  // service "" disables the watchdog (no motion is ever watched). `presence`: how recently the
  // service must have been heard for a motion starting now to be watched.
  HeartbeatWatchdog(std::string service, Milliseconds timeout,
                    Milliseconds presence = Milliseconds(5000));

  const std::string& service() const { return service_; }
  bool enabled() const { return !service_.empty(); }

  // A heartbeat of the watched service arrived; `healthy` is false for STOPPING and ERROR,
  // `state` names the state for the stop reason.
  void Heard(TimePoint now, bool healthy, std::string state);
  // Whether a motion starting at `now` is watched.
  bool ShouldWatch(TimePoint now) const;
  // What is wrong with the watched service at `now` ("<service> heartbeat lost for N ms" or
  // "<service> reported ERROR"), or "" while it is alive and well (or was never heard).
  std::string Problem(TimePoint now) const;
  // For a watched motion: Problem() and that the arm was stopped, or "".
  std::string StopReason(TimePoint now) const;

 private:
  std::string service_;
  Milliseconds timeout_;
  Milliseconds presence_;
  std::optional<TimePoint> last_heard_;
  bool healthy_ = true;
  std::string state_;
};

}  // namespace avc::robot
