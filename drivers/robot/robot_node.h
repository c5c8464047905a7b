#pragma once

// avc-robot's bus node: maps robot_command_t to the UR5 library (safety envelope check, URScript
// on the secondary interface, dashboard calls), answers with ack_t (ACCEPTED/REFUSED, then
// DONE/FAILED; a repeated request id gets its last answer again, nothing is re-executed) and
// publishes robot_state_t from the RTDE stream. Runs on an EventLoop (its own 8 ms poll timer)
// and keeps the service heartbeat: READY idle, BUSY moving, ERROR without a controller.
//  - A lost controller (or one not there at start) never ends the process: the active motion
//    FAILS with the reason, commands are REFUSED with it, and the three interfaces are
//    reconnected with exponential backoff (250 ms doubling to 5 s).
//  - Watchdog: a motion started while the watched service (the orchestrator) is alive is
//    stopped (stopj) and FAILS when that service's heartbeat goes silent or it reports
//    STOPPING/ERROR, so a dead orchestrator never leaves the arm driving.

#include <avc/ack_t.hpp>
#include <avc/heartbeat_t.hpp>
#include <avc/robot_command_t.hpp>
#include <chrono>
#include <optional>
#include <string>

#include "core/auth/command_auth.h"
#include "core/bus/ack_book.h"
#include "core/bus/bus.h"
#include "core/bus/event_loop.h"
#include "core/bus/heartbeat.h"
#include "core/kinematics/dh_parameters.h"
#include "core/kinematics/safety_envelope.h"
#include "drivers/robot/controller_link.h"
#include "drivers/robot/heartbeat_watchdog.h"
#include "drivers/robot/motion_monitor.h"

namespace avc::robot {

struct RobotNodeConfig {
  std::string service = "avc-robot";
  std::string host = "127.0.0.1";
  uint16_t rtde_port = 30004;
  uint16_t secondary_port = 30002;
  uint16_t dashboard_port = 29999;
  net::Milliseconds connect_timeout{2000};
  net::Milliseconds poll_period{8};  // the CB3 control period
  net::Milliseconds reconnect_min{250};
  net::Milliseconds reconnect_max{5000};
  // Nominal arm for envelope checks (planning only; reported poses come from the controller).
  kinematics::DhParameters dh = kinematics::NominalUr5();
  kinematics::SafetyEnvelope envelope;
  double default_joint_speed = 0.5;          // rad/s, when a command says 0
  double default_joint_acceleration = 1.0;   // rad/s^2
  double default_linear_speed = 0.1;         // m/s
  double default_linear_acceleration = 0.5;  // m/s^2
  double stop_deceleration = 2.0;            // rad/s^2 of stopj (STOP, watchdog, shutdown)
  MotionTolerance tolerance;
  net::Milliseconds motion_timeout{60000};
  // Power on, brake release, unlock and power off are DONE once the controller reports the mode
  // they lead to (brakes take seconds to release), FAILED if that takes longer than this.
  net::Milliseconds mode_change_timeout{30000};
  double state_rate_hz = 25;  // robot_state_t publication rate (controller time)
  // The service whose heartbeat guards motions ("" disables the watchdog).
  std::string watchdog_service = "avc-orchestrator";
  // Silence after which a watched motion is stopped: with the stop itself taking about 25 ms,
  // the arm is stopped within 500 ms of losing the orchestrator (which beats at 10 Hz).
  net::Milliseconds watchdog_timeout{400};
  // Who may move the arm: every command but STOP and POWER_OFF must be signed with the cell's
  // key (core/auth) unless unsigned commands are allowed explicitly.
  auth::VerifierOptions auth;

  // Empty when usable, else what is wrong.
  std::string Validate() const;
};

class RobotNode {
 public:
  // Subscribes to ROBOT_COMMAND and HEARTBEAT, tries the first connection at once and starts
  // polling. Throws std::invalid_argument for a bad config (never for a missing controller).
  RobotNode(bus::Bus& bus, bus::EventLoop& loop, bus::HeartbeatPublisher& heartbeat,
            RobotNodeConfig config);
  ~RobotNode();
  RobotNode(const RobotNode&) = delete;
  RobotNode& operator=(const RobotNode&) = delete;

  // Before the process ends: stops the arm if a motion is running (it FAILS).
  void Shutdown();

  // Handles one command (the ROBOT_COMMAND subscription calls this).
  void Handle(const avc::robot_command_t& command);

  bool connected() const { return link_.connected(); }
  const std::optional<RobotState>& last_state() const { return last_state_; }
  // The controller's KINEMATICS_INFO as read at the last connect (nullopt when it never came).
  const std::optional<primary::KinematicsInfo>& controller_kinematics() const {
    return link_.kinematics();
  }

 private:
  struct ActiveMotion {
    std::string request_id;
    MotionMonitor monitor;
    std::chrono::steady_clock::time_point deadline;
    int reached_in_a_row = 0;
    bool watched = false;
  };

  void Tick();
  void TryConnect();
  void ControllerLost(const std::string& what);
  // Reads every state that arrived and finishes the active motion when it ends; throws on a
  // lost interface.
  void Poll();
  void CheckWatchdog();
  void OnHeartbeat(const avc::heartbeat_t& beat);
  void UpdateHeartbeat();

  void Ack(const std::string& request_id, int8_t status, const std::string& reason);
  // True when the command is authentic and for this cell; else the refusal is sent and logged.
  bool Authentic(const avc::robot_command_t& command);
  // Why no motion can start yet (busy, no state from the controller yet), or empty.
  std::string MotionNotReady() const;
  // Returns a refusal reason, or empty after the motion was sent (MotionNotReady() was empty).
  std::string StartMotion(const avc::robot_command_t& command);
  std::string RunDashboard(const avc::robot_command_t& command);
  void Stop(const avc::robot_command_t& command);
  // Sets the plant's keep-out from the command's slabs, or clears it when there are none; the
  // reason when the values are unusable (nothing changes then).
  std::string SetPlantKeepOut(const avc::robot_command_t& command);
  void Finish(int8_t status, std::string reason);  // by value: reasons often come from active_
  void PublishState(const RobotState& state);
  void LogControllerKinematics();

  bus::Bus& bus_;
  bus::EventLoop& loop_;
  bus::HeartbeatPublisher& heartbeat_;
  RobotNodeConfig config_;
  bus::AckBook acks_;
  std::optional<auth::CommandVerifier> verifier_;
  ControllerLink link_;
  HeartbeatWatchdog watchdog_;
  bool unwatched_logged_ = false;
  bool shut_down_ = false;
  std::string error_;  // why there is no controller; "" while connected
  net::Milliseconds reconnect_delay_;
  std::chrono::steady_clock::time_point next_connect_;
  bus::Bus::SubscriptionId command_subscription_ = 0;
  bus::Bus::SubscriptionId heartbeat_subscription_ = 0;
  bus::EventLoop::TimerId timer_ = 0;
  std::optional<RobotState> last_state_;
  double last_published_time_ = -1e9;
  std::optional<ActiveMotion> active_;
  // A dashboard command waiting for the controller's mode to follow.
  struct ModeChange {
    std::string request_id;
    int8_t kind = 0;
    std::chrono::steady_clock::time_point deadline;
  };
  std::optional<ModeChange> mode_change_;
  void StartModeChange(const avc::robot_command_t& command);
  void CheckModeChange();
  void FinishModeChange(int8_t status, const std::string& reason);
};

}  // namespace avc::robot
