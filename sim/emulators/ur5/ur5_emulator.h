#pragma once

// A protocol-level UR5 (CB3) emulator: RTDE (30004), primary (30001) and secondary (30002)
// script-and-state interfaces and the dashboard server (29999) on configurable ports, driving a
// simulated arm whose reported TCP pose comes from the TRUE (perturbed) kinematics of a
// sim::CellTruth. One thread runs the 125 Hz control tick, paced by the cell's shared
// EmulatorClock (so a scaled or stepped clock runs the arm faster than real time), and serves
// every socket between ticks. Fault injection: protective stop (now or at a fraction of the next
// move) and dropping every client connection.

#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <thread>

#include "core/kinematics/dh_parameters.h"
#include "drivers/robot/protocol/ur_modes.h"
#include "sim/emulators/clock/emulator_clock.h"
#include "sim/emulators/ur5/ur5_emulator_options.h"

namespace avc::sim::ur5 {

// What the controller would report right now, and the truth behind it.
struct Ur5Snapshot {
  double time = 0;  // controller time: the shared clock at the last control tick
  kinematics::JointVector true_q;
  kinematics::JointVector reported_q;
  Eigen::Isometry3d true_T_base_flange = Eigen::Isometry3d::Identity();
  robot::RobotMode robot_mode = robot::RobotMode::kPowerOff;
  robot::SafetyMode safety_mode = robot::SafetyMode::kNormal;
  bool program_running = false;
  int rtde_clients = 0;    // streaming RTDE sessions
  int script_clients = 0;  // primary and secondary sessions
  int scripts_run = 0;
};

class Ur5Emulator {
 public:
  // Binds every port and starts the loop thread on `clock` (nullptr: real time). Throws
  // std::invalid_argument for bad options and net::ConnectionError when a port cannot be
  // bound.
  explicit Ur5Emulator(Ur5EmulatorOptions options, std::shared_ptr<EmulatorClock> clock = nullptr);
  ~Ur5Emulator();
  Ur5Emulator(const Ur5Emulator&) = delete;
  Ur5Emulator& operator=(const Ur5Emulator&) = delete;

  uint16_t rtde_port() const;
  uint16_t primary_port() const;
  uint16_t secondary_port() const;
  uint16_t dashboard_port() const;

  Ur5Snapshot Snapshot() const;
  // The true flange pose in base: forward kinematics of the TRUE DH set at the TRUE joints (what
  // the simulated cell mounts its camera on).
  Eigen::Isometry3d TrueBaseFromFlange() const;

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
