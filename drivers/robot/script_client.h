#pragma once

// Sends URScript programs to the secondary interface (30002; the primary 30001 works the same) and
// reads back what the controller says: runtime exceptions and text messages, and the 10 Hz
// ROBOT_STATE stream. Keeps the socket open and drains it (the controller may discard a script
// whose socket closes before it read the stream).

#include <optional>
#include <string>
#include <vector>

#include "core/net/tcp_socket.h"
#include "drivers/robot/protocol/primary_protocol.h"
#include "drivers/robot/protocol/primary_robot_state.h"

namespace avc::robot {

class ScriptClient {
 public:
  ScriptClient(const std::string& host, uint16_t port,
               net::Milliseconds timeout = net::Milliseconds(2000));

  // Sends a program (a trailing newline is added when missing).
  void Send(const std::string& program);
  // Robot messages (text and runtime exceptions) received within `timeout`; reading stops at the
  // first message or the timeout. Throws net::ConnectionError on disconnect.
  std::vector<primary::RobotMessage> Poll(net::Milliseconds timeout);

  // What the controller announced on this connection (VERSION on connect, KINEMATICS_INFO in
  // its ROBOT_STATE stream); filled by Poll.
  const std::optional<primary::VersionMessage>& version() const { return version_; }
  const std::optional<primary::KinematicsInfo>& kinematics() const { return kinematics_; }
  // The newest ROBOT_MODE_DATA / JOINT_DATA / CARTESIAN_INFO of the ROBOT_STATE stream.
  const std::optional<primary::RobotModeData>& robot_mode_data() const { return mode_; }
  const std::optional<primary::JointData>& joint_data() const { return joints_; }
  const std::optional<primary::CartesianInfo>& cartesian_info() const { return cartesian_; }
  // ROBOT_STATE messages decoded so far.
  int robot_states_received() const { return robot_states_received_; }
  // Polls until KINEMATICS_INFO arrived or `timeout` passed; returns it when it did.
  std::optional<primary::KinematicsInfo> WaitForKinematics(net::Milliseconds timeout);

  const std::string& peer() const { return stream_.peer(); }

 private:
  void Absorb(primary::RobotStateMessage state);

  net::TcpStream stream_;
  net::Milliseconds timeout_;
  primary::PackageFramer framer_;
  std::optional<primary::VersionMessage> version_;
  std::optional<primary::KinematicsInfo> kinematics_;
  std::optional<primary::RobotModeData> mode_;
  std::optional<primary::JointData> joints_;
  std::optional<primary::CartesianInfo> cartesian_;
  int robot_states_received_ = 0;
  std::vector<primary::RobotMessage> unread_;
};

}  // namespace avc::robot
