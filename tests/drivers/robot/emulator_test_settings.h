#pragma once

// What the UR5 emulator tests of this folder share: the emulator on the loopback interface with
// encoder noise small enough that positions compare at its size.

#include <string>

namespace avc::testing {

inline constexpr double kEncoderNoise = 1e-5;  // rad
inline const std::string kEmulatorHost = "127.0.0.1";

}  // namespace avc::testing
