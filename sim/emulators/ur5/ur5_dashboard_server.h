#pragma once

// The emulated controller's dashboard server (29999): the banner on connect, then one reply line
// per command line (as Universal Robots' dashboard server manual gives them), acting on the
// controller's robot-mode state machine.

#include <string>

#include "sim/emulators/ur5/ur5_controller.h"
#include "sim/emulators/ur5/ur5_session.h"

namespace avc::sim::ur5 {

inline constexpr std::string_view kDashboardBannerLine =
    "Connected: Universal Robots Dashboard Server\n";

// The reply to one command line (without the line end); `hang_up` is set by "quit".
std::string DashboardReply(Ur5Controller& controller, const std::string& line, bool& hang_up);

class DashboardSession final : public Session {
 public:
  DashboardSession(int id, net::TcpStream stream, Ur5Controller& controller);

 private:
  void Consume(const uint8_t* data, size_t size) override;

  Ur5Controller& controller_;
  std::string line_buffer_;
};

}  // namespace avc::sim::ur5
