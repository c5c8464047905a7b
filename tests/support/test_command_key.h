#pragma once

// A fixed motion-command key for in-process driver tests (no key file needed).

#include <cstddef>
#include <cstdint>

#include "core/auth/command_key.h"

namespace avc::testing {

inline auth::CommandKey TestCommandKey() {
  auth::CommandKey key;
  for (size_t i = 0; i < key.bytes.size(); ++i) key.bytes[i] = static_cast<uint8_t>(7 * i + 1);
  return key;
}

}  // namespace avc::testing
