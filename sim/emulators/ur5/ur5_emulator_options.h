#pragma once

// How an emulated UR5 (CB3) is set up: which arm it is (the TRUE, perturbed kinematics of a
// sim::CellTruth), where it listens, what software it reports, its noise and starting state.

#include <cstdint>
#include <string>

#include "core/kinematics/dh_parameters.h"
#include "drivers/robot/protocol/rtde_protocol.h"
#include "sim/cell/cell_truth.h"

namespace avc::sim::ur5 {

struct Ur5EmulatorOptions {
  CellTruth cell = NominalCell();
  std::string host = "127.0.0.1";
  // 0 picks an ephemeral port (tests); the real controller's ports are the defaults.
  uint16_t rtde_port = 30004;
  uint16_t primary_port = 30001;
  uint16_t secondary_port = 30002;
  uint16_t dashboard_port = 29999;
  int max_protocol_version = 2;  // 1 emulates an old controller (tests the client's fallback)
  robot::rtde::ControllerVersion version{3, 15, 7, 106331};
  double control_frequency = 125.0;  // CB3 control loop and highest RTDE rate
  double encoder_noise_rad = 1e-5;   // uniform +- on every reported joint angle
  uint64_t seed = 1;
  kinematics::JointVector initial_q =
      (kinematics::JointVector() << 0, -1.5707963267948966, 1.5707963267948966, -1.5707963267948966,
       -1.5707963267948966, 0)
          .finished();
  bool powered = false;  // start in RUNNING (true) or POWER_OFF (false)

  // Empty when usable, else the first bad field.
  std::string Validate() const;
};

}  // namespace avc::sim::ur5
