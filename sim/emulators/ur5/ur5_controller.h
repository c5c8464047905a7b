#pragma once

// The emulated CB3 controller behind every interface: the arm (ur5_arm.h) on the TRUE kinematics,
// robot and safety modes, the running URScript program, encoder noise, the RTDE variable table
// and the ROBOT_STATE contents. No sockets and no clock: the emulator calls Tick once per control
// period with the shared clock's time, and the interface sessions call the rest. Not thread-safe;
// the emulator serialises every call.

#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "drivers/robot/protocol/primary_protocol.h"
#include "drivers/robot/protocol/primary_robot_state.h"
#include "drivers/robot/protocol/ur_modes.h"
#include "sim/emulators/ur5/ur5_arm.h"
#include "sim/emulators/ur5/ur5_emulator_options.h"
#include "sim/emulators/ur5/ur5_rtde_variables.h"
#include "sim/emulators/ur5/ur5_script.h"

namespace avc::sim::ur5 {

// A framed primary/secondary package for the script session `session_id` (runtime exceptions go
// back to the connection that sent the program).
struct SessionMessage {
  int session_id = 0;
  std::vector<uint8_t> bytes;
};

class Ur5Controller {
 public:
  // `start_time`: the shared clock's reading when the controller boots (its time base).
  Ur5Controller(const Ur5EmulatorOptions& options, double start_time);

  const Ur5EmulatorOptions& options() const { return options_; }
  double dt() const { return dt_; }
  double time() const { return time_; }

  // One control period, ending at clock time `time`: runs the program, moves the arm, samples
  // the encoders.
  void Tick(double time);

  // URScript from a primary/secondary session: a parsed unit (ur5_script.h). A new program
  // aborts the running one.
  void RunScript(int session_id, const std::vector<std::string>& lines);
  // Messages produced since the last call (each for one session; drop those of closed ones).
  std::vector<SessionMessage> TakeMessages();

  // Dashboard actions (robot-mode state machine POWER_OFF -> IDLE -> RUNNING).
  void PowerOn();
  void PowerOff();
  void BrakeRelease();
  // False when the robot is not protective-stopped.
  bool UnlockProtectiveStop();
  // Dashboard "stop": aborts the program and brakes.
  void StopProgram();

  // Fault injection.
  void ProtectiveStop();
  // The next motion is protective-stopped once it covered `fraction` of its path.
  void ArmProtectiveStopAt(double fraction) { stop_at_fraction_ = fraction; }

  robot::RobotMode robot_mode() const { return robot_mode_; }
  robot::SafetyMode safety_mode() const { return safety_mode_; }
  bool program_running() const { return program_.has_value(); }
  int scripts_run() const { return scripts_run_; }
  const JointVector& true_q() const { return arm_.q(); }
  const JointVector& reported_q() const { return reported_q_; }
  // Forward kinematics of the TRUE DH set at the TRUE joints (no encoder noise).
  Eigen::Isometry3d TrueBaseFromFlange() const;

  // RTDE variables (outputs as of the last tick; inputs as the clients wrote them).
  const ControllerState& rtde_state() const { return rtde_state_; }
  void WriteRtdeInput(const std::string& name, const robot::rtde::Value& value);

  // What the primary/secondary interfaces announce.
  robot::primary::VersionMessage Version() const;
  robot::primary::RobotStateMessage PrimaryState() const;

 private:
  struct Program {
    std::vector<ScriptStatement> statements;
    size_t next = 0;
    int session_id = 0;
  };

  void RuntimeError(int session_id, int line, int column, const std::string& text);
  void AdvanceProgram();
  // The encoder's error on `joint` at angle q: a fixed function of the seed, the joint and q, so
  // an arm at rest reads the same however many control ticks have passed.
  double EncoderError(int joint, double q) const;
  void SampleState();
  bool powered() const;

  Ur5EmulatorOptions options_;
  Ur5Arm arm_;
  double dt_;
  double time_;
  robot::RobotMode robot_mode_;
  robot::SafetyMode safety_mode_ = robot::SafetyMode::kNormal;
  JointVector reported_q_ = JointVector::Zero();
  ControllerState rtde_state_;
  robot::primary::KinematicsInfo kinematics_;
  std::optional<Program> program_;
  std::optional<double> stop_at_fraction_;
  std::vector<SessionMessage> messages_;
  int scripts_run_ = 0;
};

}  // namespace avc::sim::ur5
