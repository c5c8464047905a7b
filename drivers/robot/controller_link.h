#pragma once

// The three controller interfaces avc-robot needs, held together: RTDE (state stream), the
// secondary interface (URScript out, KINEMATICS_INFO and runtime errors in) and the dashboard.
// Connected means all three are; losing any one drops them all, so a reconnect always starts
// from a clean RTDE handshake and a fresh script socket.

#include <memory>
#include <optional>
#include <string>

#include "drivers/robot/dashboard_client.h"
#include "drivers/robot/rtde_client.h"
#include "drivers/robot/script_client.h"

namespace avc::robot {

struct ControllerAddress {
  std::string host = "127.0.0.1";
  uint16_t rtde_port = 30004;
  uint16_t secondary_port = 30002;
  uint16_t dashboard_port = 29999;
  net::Milliseconds timeout{2000};
};

class ControllerLink {
 public:
  explicit ControllerLink(ControllerAddress address) : address_(std::move(address)) {}

  // Connects every interface (RTDE handshake, dashboard banner) and waits up to the timeout for
  // KINEMATICS_INFO. Throws (net::ConnectionError or std::runtime_error naming the interface) and
  // stays disconnected when any part fails.
  void Connect();
  void Disconnect();
  bool connected() const { return rtde_ != nullptr; }

  // Throws net::ConnectionError when the dashboard hung up (the others notice on their own reads).
  void CheckDashboard();

  // Only while connected.
  RtdeClient& rtde() { return *rtde_; }
  ScriptClient& script() { return *script_; }
  DashboardClient& dashboard() { return *dashboard_; }
  // The controller's KINEMATICS_INFO from the last connect (nullopt when it never came).
  const std::optional<primary::KinematicsInfo>& kinematics() const { return kinematics_; }

  const ControllerAddress& address() const { return address_; }

 private:
  ControllerAddress address_;
  std::unique_ptr<RtdeClient> rtde_;
  std::unique_ptr<ScriptClient> script_;
  std::unique_ptr<DashboardClient> dashboard_;
  std::optional<primary::KinematicsInfo> kinematics_;
};

}  // namespace avc::robot
