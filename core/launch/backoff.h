#pragma once

// When to restart a process that ended: quickly the first time, then doubling so a process that
// crashes at once does not spin, and quickly again once it has proven it can stay up.

#include <chrono>

namespace avc::launch {

struct BackoffPolicy {
  std::chrono::milliseconds initial{200};
  std::chrono::milliseconds max{10'000};
  // A run at least this long resets the delay to initial.
  std::chrono::milliseconds reset_after{10'000};
};

class Backoff {
 public:
  explicit Backoff(BackoffPolicy policy = {}) : policy_(policy), next_(policy.initial) {}

  // The delay before restarting a process that just ended after running for uptime.
  std::chrono::milliseconds NextDelay(std::chrono::milliseconds uptime);
  void Reset() { next_ = policy_.initial; }

 private:
  BackoffPolicy policy_;
  std::chrono::milliseconds next_;
};

}  // namespace avc::launch
