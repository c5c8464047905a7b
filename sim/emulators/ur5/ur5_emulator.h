#pragma once

// A protocol-level UR5 (CB3) emulator: RTDE (30004), the secondary script interface (30002) and
// the dashboard server (29999) on configurable ports, driving a simulated arm whose reported TCP
// pose comes from the TRUE (perturbed) kinematics of a sim::CellTruth. One thread runs a poll
// loop over every socket and the 125 Hz control tick; `time_scale` makes simulated time run
// faster than real time so tests finish quickly. Fault injection: protective stop (now or at a
// fraction of the next move) and dropping every client connection.

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "core/kinematics/dh_parameters.h"
#include "drivers/robot/rtde_protocol.h"
#include "drivers/robot/ur_modes.h"
#include "sim/cell/cell_truth.h"

namespace avc::sim::ur5 {

struct Ur5EmulatorOptions {
  CellTruth cell = NominalCell();
  std::string host = "127.0.0.1";
  // 0 picks an ephemeral port (tests); the real controller's ports are the defaults.
  uint16_t rtde_port = 30004;
  uint16_t secondary_port = 30002;
  uint16_t dashboard_port = 29999;
  int max_protocol_version = 2;  // 1 emulates an old controller (tests the client's fallback)
  robot::rtde::ControllerVersion version{3, 15, 7, 106331};
  double control_frequency = 125.0;  // CB3 control loop and highest RTDE rate
  double time_scale = 1.0;           // simulated seconds per real second
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

// What the controller would report right now.
struct Ur5Snapshot {
  double time = 0;
  kinematics::JointVector true_q;
  kinematics::JointVector reported_q;
  robot::RobotMode robot_mode = robot::RobotMode::kPowerOff;
  robot::SafetyMode safety_mode = robot::SafetyMode::kNormal;
  bool program_running = false;
  int rtde_clients = 0;
  int scripts_run = 0;
};

class Ur5Emulator {
 public:
  // Binds every port and starts the loop thread. Throws std::invalid_argument for bad options
  // and robot::ConnectionError when a port cannot be bound.
  explicit Ur5Emulator(Ur5EmulatorOptions options);
  ~Ur5Emulator();
  Ur5Emulator(const Ur5Emulator&) = delete;
  Ur5Emulator& operator=(const Ur5Emulator&) = delete;

  uint16_t rtde_port() const;
  uint16_t secondary_port() const;
  uint16_t dashboard_port() const;

  Ur5Snapshot Snapshot() const;

  // Fault injection.
  void TriggerProtectiveStop();
  // The next motion is protective-stopped once it covered `fraction` (0..1) of its path.
  void ArmProtectiveStopAt(double fraction);
  // Closes every client connection (listeners stay open, so clients can reconnect).
  void DropConnections();

  // Stops the loop and closes every socket; called by the destructor.
  void Stop();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::thread thread_;
};

}  // namespace avc::sim::ur5
