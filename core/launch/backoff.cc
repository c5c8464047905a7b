#include "core/launch/backoff.h"

#include <algorithm>

namespace avc::launch {

std::chrono::milliseconds Backoff::NextDelay(std::chrono::milliseconds uptime) {
  if (uptime >= policy_.reset_after) Reset();
  const std::chrono::milliseconds delay = next_;
  next_ = std::min(next_ * 2, policy_.max);
  return delay;
}

}  // namespace avc::launch
