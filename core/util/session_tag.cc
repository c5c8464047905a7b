#include "core/util/session_tag.h"

#include <fmt/format.h>
#include <unistd.h>

#include <atomic>
#include <cstdint>

#include "core/util/clock.h"

namespace avc {

std::string SessionTag() {
  static std::atomic<int> tags{0};
  return fmt::format("{:x}{:x}{}", static_cast<uint32_t>(getpid()),
                     static_cast<uint64_t>(SystemClock().NowMicros()) & 0xffffff, tags++);
}

}  // namespace avc
