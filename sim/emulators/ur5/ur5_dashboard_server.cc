#include "sim/emulators/ur5/ur5_dashboard_server.h"

#include <fmt/format.h>

#include <cctype>

#include "core/util/trim.h"

namespace avc::sim::ur5 {
namespace {

std::string Lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

}  // namespace

std::string DashboardReply(Ur5Controller& controller, const std::string& line, bool& hang_up) {
  const std::string command = Lower(std::string(TrimSpace(line)));
  if (command == "power on") {
    controller.PowerOn();
    return "Powering on";
  }
  if (command == "power off") {
    controller.PowerOff();
    return "Powering off";
  }
  if (command == "brake release") {
    controller.BrakeRelease();
    return "Brake releasing";
  }
  if (command == "robotmode") {
    return fmt::format("Robotmode: {}", RobotModeName(controller.robot_mode()));
  }
  if (command == "safetymode") {
    return fmt::format("Safetymode: {}", SafetyModeName(controller.safety_mode()));
  }
  if (command == "safetystatus") {
    return fmt::format("Safetystatus: {}", SafetyModeName(controller.safety_mode()));
  }
  if (command == "unlock protective stop") {
    return controller.UnlockProtectiveStop()
               ? "Protective stop releasing"
               : "Cannot unlock protective stop, robot is not protective stopped";
  }
  if (command == "close safety popup") return "closing safety popup";
  if (command == "close popup") return "closing popup";
  if (command == "polyscopeversion") {
    const auto& version = controller.options().version;
    return fmt::format("URSoftware {}.{}.{}.{} (emulated)", version.major, version.minor,
                       version.bugfix, version.build);
  }
  if (command == "get robot model") return "UR5";
  if (command == "get serial number") return "EMULATED-UR5";
  if (command == "running") {
    return fmt::format("Program running: {}", controller.program_running() ? "true" : "false");
  }
  if (command == "programstate") {
    return controller.program_running() ? "PLAYING avc" : "STOPPED <unnamed>";
  }
  if (command == "stop") {
    controller.StopProgram();
    return "Stopped";
  }
  if (command == "quit") {
    hang_up = true;
    return "Disconnected";
  }
  return fmt::format("could not understand: '{}'", std::string(TrimSpace(line)));
}

DashboardSession::DashboardSession(int id, net::TcpStream stream, Ur5Controller& controller)
    : Session(id, std::move(stream)), controller_(controller) {
  Queue(std::string(kDashboardBannerLine));
}

void DashboardSession::Consume(const uint8_t* data, size_t size) {
  line_buffer_.append(reinterpret_cast<const char*>(data), size);
  size_t end;
  while ((end = line_buffer_.find('\n')) != std::string::npos) {
    const std::string line = line_buffer_.substr(0, end);
    line_buffer_.erase(0, end + 1);
    bool hang_up = false;
    Queue(DashboardReply(controller_, line, hang_up) + "\n");
    if (hang_up) HangUpAfterFlush();
  }
}

}  // namespace avc::sim::ur5
