#include "drivers/robot/controller_link.h"

namespace avc::robot {

void ControllerLink::Connect() {
  Disconnect();
  const ControllerAddress& a = address_;
  auto rtde = std::make_unique<RtdeClient>(a.host, a.rtde_port, a.timeout);
  rtde->Handshake();
  auto script = std::make_unique<ScriptClient>(a.host, a.secondary_port, a.timeout);
  auto dashboard = std::make_unique<DashboardClient>(a.host, a.dashboard_port, a.timeout);
  kinematics_ = script->WaitForKinematics(a.timeout);
  rtde_ = std::move(rtde);
  script_ = std::move(script);
  dashboard_ = std::move(dashboard);
}

void ControllerLink::Disconnect() {
  rtde_.reset();
  script_.reset();
  dashboard_.reset();
}

void ControllerLink::CheckDashboard() {
  if (dashboard_) dashboard_->CheckConnected();
}

}  // namespace avc::robot
