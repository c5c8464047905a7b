#pragma once

// avc-robot's bus node: maps robot_command_t to the UR5 library (safety envelope check, URScript
// on the secondary interface, dashboard calls), answers with ack_t (ACCEPTED/REFUSED, then
// DONE/FAILED; a repeated request id gets its last answer again, nothing is re-executed) and
// publishes robot_state_t from the RTDE stream. Single-threaded: the owner calls Poll() often
// (every control period) on the thread that dispatches the bus.

#include <avc/ack_t.hpp>
#include <avc/robot_command_t.hpp>
#include <chrono>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "core/bus/bus.h"
#include "core/kinematics/dh_parameters.h"
#include "drivers/robot/dashboard_client.h"
#include "drivers/robot/motion_monitor.h"
#include "drivers/robot/rtde_client.h"
#include "drivers/robot/safety_envelope.h"
#include "drivers/robot/script_client.h"

namespace avc::robot {

struct RobotNodeConfig {
  std::string service = "avc-robot";
  std::string host = "127.0.0.1";
  uint16_t rtde_port = 30004;
  uint16_t secondary_port = 30002;
  uint16_t dashboard_port = 29999;
  Milliseconds connect_timeout{2000};
  // Nominal arm for envelope checks (planning only; reported poses come from the controller).
  kinematics::DhParameters dh = kinematics::NominalUr5();
  SafetyEnvelope envelope;
  double default_joint_speed = 0.5;          // rad/s, when a command says 0
  double default_joint_acceleration = 1.0;   // rad/s^2
  double default_linear_speed = 0.1;         // m/s
  double default_linear_acceleration = 0.5;  // m/s^2
  MotionTolerance tolerance;
  std::chrono::milliseconds motion_timeout{60000};
  double state_rate_hz = 25;  // robot_state_t publication rate (controller time)
};

class RobotNode {
 public:
  // Connects to the controller's three interfaces and subscribes to ROBOT_COMMAND. Throws
  // ConnectionError / std::runtime_error naming the interface that failed.
  RobotNode(bus::Bus& bus, RobotNodeConfig config);
  ~RobotNode();
  RobotNode(const RobotNode&) = delete;
  RobotNode& operator=(const RobotNode&) = delete;

  // Reads every state that arrived, finishes the active motion when it ends, publishes
  // robot_state_t. Controller disconnects fail the active motion and are rethrown.
  void Poll();

  // Handles one command (the ROBOT_COMMAND subscription calls this).
  void Handle(const avc::robot_command_t& command);

  const std::optional<RobotState>& last_state() const { return last_state_; }
  // The controller's KINEMATICS_INFO as read at connect (nullopt when it never came).
  const std::optional<primary::KinematicsInfo>& controller_kinematics() const {
    return kinematics_;
  }

 private:
  struct ActiveMotion {
    std::string request_id;
    MotionMonitor monitor;
    std::chrono::steady_clock::time_point deadline;
    int reached_in_a_row = 0;
  };

  void Ack(const std::string& request_id, int8_t status, const std::string& reason);
  // Returns a refusal reason, or empty after the motion was sent.
  std::string StartMotion(const avc::robot_command_t& command);
  std::string RunDashboard(const avc::robot_command_t& command);
  void Finish(int8_t status, std::string reason);  // by value: reasons often come from active_
  void PublishState(const RobotState& state);
  void LogControllerKinematics();

  bus::Bus& bus_;
  RobotNodeConfig config_;
  RtdeClient rtde_;
  ScriptClient script_;
  DashboardClient dashboard_;
  bus::Bus::SubscriptionId subscription_ = 0;
  std::optional<RobotState> last_state_;
  std::optional<primary::KinematicsInfo> kinematics_;
  double last_published_time_ = -1e9;
  std::optional<ActiveMotion> active_;
  std::map<std::string, avc::ack_t> answered_;
};

// Rows of a row-major 4x4 into a rigid transform, and back.
Eigen::Isometry3d IsometryFromRowMajor(const double* values);
void RowMajorFromIsometry(const Eigen::Isometry3d& pose, double* values);

}  // namespace avc::robot
