#include "drivers/robot/protocol/ur_modes.h"

#include <array>
#include <utility>

namespace avc::robot {
namespace {

constexpr std::array<std::pair<RobotMode, std::string_view>, 9> kRobotModes = {{
    {RobotMode::kNoController, "NO_CONTROLLER"},
    {RobotMode::kDisconnected, "DISCONNECTED"},
    {RobotMode::kConfirmSafety, "CONFIRM_SAFETY"},
    {RobotMode::kBooting, "BOOTING"},
    {RobotMode::kPowerOff, "POWER_OFF"},
    {RobotMode::kPowerOn, "POWER_ON"},
    {RobotMode::kIdle, "IDLE"},
    {RobotMode::kBackdrive, "BACKDRIVE"},
    {RobotMode::kRunning, "RUNNING"},
}};

constexpr std::array<std::pair<SafetyMode, std::string_view>, 9> kSafetyModes = {{
    {SafetyMode::kNormal, "NORMAL"},
    {SafetyMode::kReduced, "REDUCED"},
    {SafetyMode::kProtectiveStop, "PROTECTIVE_STOP"},
    {SafetyMode::kRecovery, "RECOVERY"},
    {SafetyMode::kSafeguardStop, "SAFEGUARD_STOP"},
    {SafetyMode::kSystemEmergencyStop, "SYSTEM_EMERGENCY_STOP"},
    {SafetyMode::kRobotEmergencyStop, "ROBOT_EMERGENCY_STOP"},
    {SafetyMode::kViolation, "VIOLATION"},
    {SafetyMode::kFault, "FAULT"},
}};

template <typename Table, typename Enum>
std::string_view NameIn(const Table& table, Enum value) {
  for (const auto& [entry, name] : table) {
    if (entry == value) return name;
  }
  return "UNKNOWN";
}

template <typename Table>
auto ParseIn(const Table& table, std::string_view name)
    -> std::optional<typename Table::value_type::first_type> {
  for (const auto& [entry, entry_name] : table) {
    if (entry_name == name) return entry;
  }
  return std::nullopt;
}

}  // namespace

std::string_view RobotModeName(RobotMode mode) { return NameIn(kRobotModes, mode); }
std::string_view SafetyModeName(SafetyMode mode) { return NameIn(kSafetyModes, mode); }
std::optional<RobotMode> ParseRobotMode(std::string_view name) {
  return ParseIn(kRobotModes, name);
}
std::optional<SafetyMode> ParseSafetyMode(std::string_view name) {
  return ParseIn(kSafetyModes, name);
}

}  // namespace avc::robot
