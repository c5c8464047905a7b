#pragma once

// Controller state enums as RTDE reports them (numbers) and the dashboard prints them (names);
// values from Universal_Robots_Client_Library ur/datatypes.h.

#include <cstdint>
#include <optional>
#include <string_view>

namespace avc::robot {

enum class RobotMode : int32_t {
  kNoController = -1,
  kDisconnected = 0,
  kConfirmSafety = 1,
  kBooting = 2,
  kPowerOff = 3,
  kPowerOn = 4,
  kIdle = 5,
  kBackdrive = 6,
  kRunning = 7,
};

enum class SafetyMode : int32_t {
  kNormal = 1,
  kReduced = 2,
  kProtectiveStop = 3,
  kRecovery = 4,
  kSafeguardStop = 5,
  kSystemEmergencyStop = 6,
  kRobotEmergencyStop = 7,
  kViolation = 8,
  kFault = 9,
};

enum class RuntimeState : uint32_t {
  kStopping = 0,
  kStopped = 1,
  kPlaying = 2,
  kPausing = 3,
  kPaused = 4,
  kResuming = 5,
};

// robot_status_bits and safety_status_bits bits we use.
inline constexpr uint32_t kStatusPowerOn = 1u << 0;
inline constexpr uint32_t kStatusProgramRunning = 1u << 1;
inline constexpr uint32_t kSafetyNormal = 1u << 0;
inline constexpr uint32_t kSafetyProtectiveStopped = 1u << 2;

// "RUNNING", "PROTECTIVE_STOP", ... as the dashboard prints them; "UNKNOWN" otherwise.
std::string_view RobotModeName(RobotMode mode);
std::string_view SafetyModeName(SafetyMode mode);
std::optional<RobotMode> ParseRobotMode(std::string_view name);
std::optional<SafetyMode> ParseSafetyMode(std::string_view name);

}  // namespace avc::robot
