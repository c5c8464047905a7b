#pragma once

// The emulated controller's primary (30001) and secondary (30002) interfaces, which behave alike
// here: VERSION and a ROBOT_STATE on connect, then ROBOT_STATE (ROBOT_MODE_DATA, JOINT_DATA,
// CARTESIAN_INFO, KINEMATICS_INFO) at 10 Hz of controller time, and URScript in: `def`/`sec`
// blocks and one-line statements run on the controller; its runtime exceptions come back on the
// session that sent the program.

#include "sim/emulators/ur5/ur5_controller.h"
#include "sim/emulators/ur5/ur5_script.h"
#include "sim/emulators/ur5/ur5_session.h"

namespace avc::sim::ur5 {

inline constexpr double kRobotStatePeriod = 0.1;  // s of controller time

class PrimarySession final : public Session {
 public:
  PrimarySession(int id, net::TcpStream stream, Ur5Controller& controller);

  void OnTick() override;

 private:
  void Consume(const uint8_t* data, size_t size) override;
  void QueueState();

  Ur5Controller& controller_;
  ScriptAssembler assembler_;
  double since_state_ = 0;
};

}  // namespace avc::sim::ur5
