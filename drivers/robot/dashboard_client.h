#pragma once

// Dashboard server client (port 29999): one ASCII command per line, one reply line each. Replies
// are checked against what the controller prints (Universal_Robots_Client_Library
// dashboard_client_implementation_g5.cpp); an unexpected reply throws naming the command.

#include <string>

#include "core/net/tcp_socket.h"
#include "drivers/robot/protocol/ur_modes.h"

namespace avc::robot {

inline constexpr std::string_view kDashboardBanner = "Connected: Universal Robots Dashboard Server";

class DashboardClient {
 public:
  // Connects and reads the banner; throws when the banner is not the dashboard's.
  DashboardClient(const std::string& host, uint16_t port,
                  net::Milliseconds timeout = net::Milliseconds(2000));

  // Sends one command line and returns the reply line without its line end.
  std::string Command(const std::string& command);

  void PowerOn();               // "Powering on"
  void PowerOff();              // "Powering off"
  void BrakeRelease();          // "Brake releasing"
  void UnlockProtectiveStop();  // "Protective stop releasing"
  void CloseSafetyPopup();      // "closing safety popup"
  RobotMode GetRobotMode();     // "Robotmode: RUNNING"
  SafetyMode GetSafetyMode();   // "Safetymode: NORMAL"
  std::string SafetyStatus();   // "Safetystatus: NORMAL" (>= 5.4); the text after the colon
  std::string PolyscopeVersion();

  // Notices, without waiting, a connection the server closed: throws net::ConnectionError naming
  // the peer (the dashboard sends nothing unasked, so a closed socket is the only thing to read).
  void CheckConnected();

  const std::string& banner() const { return banner_; }

 private:
  std::string ReadLine(const std::string& step);
  // Sends `command` and throws unless the reply starts with `expected`.
  std::string Expect(const std::string& command, std::string_view expected);

  net::TcpStream stream_;
  net::Milliseconds timeout_;
  std::string buffer_;
  std::string banner_;
};

// "Robotmode: RUNNING" -> the text after "<prefix>: ", trimmed; throws when the prefix differs.
std::string ReplyValue(const std::string& reply, std::string_view prefix);

}  // namespace avc::robot
