#pragma once

// RTDE client (port 30004): the handshake of Universal_Robots_Client_Library setupCommunication()
// — protocol 2 with fallback to 1, controller version, output recipe, input recipes, start — and
// the state stream at the controller's rate. Every error names host:port and the step.

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "core/net/tcp_socket.h"
#include "drivers/robot/protocol/rtde_protocol.h"
#include "drivers/robot/robot_state.h"

namespace avc::robot {

// CB3 controllers (major version < 5) stream at most 125 Hz, e-Series 500 Hz.
inline constexpr double kCb3MaxFrequency = 125.0;
inline constexpr double kESeriesMaxFrequency = 500.0;

struct RtdeSample {
  rtde::DataPackage package;
  RobotState state;
};

class RtdeClient {
 public:
  // Connects; throws net::ConnectionError naming host:port.
  RtdeClient(std::string host, uint16_t port, net::Milliseconds timeout = net::Milliseconds(2000));

  // Asks for protocol 2, then 1; returns the accepted version. Throws when neither is accepted.
  int NegotiateProtocol();
  rtde::ControllerVersion GetControllerVersion();
  // The highest rate the controller streams at (from its major version).
  double MaxFrequency() const { return max_frequency_; }

  // Registers the output recipe; throws std::runtime_error listing the variables the controller
  // does not know (NOT_FOUND) or when the frequency is outside (0, MaxFrequency()].
  void SetupOutputs(double frequency, const std::vector<std::string>& names);
  // Registers an input recipe and returns its id; throws listing NOT_FOUND and IN_USE variables.
  uint8_t SetupInputs(const std::vector<std::string>& names);
  void Start();
  void Pause();

  // Writes an input recipe's values.
  void SendInputs(uint8_t recipe_id, const std::vector<rtde::Value>& values);

  // The next data package, waiting up to `timeout`; nullopt when none arrived in time. Text
  // messages arriving meanwhile are kept (TakeTextMessages). Throws net::ConnectionError on
  // disconnect.
  std::optional<RtdeSample> Receive(net::Milliseconds timeout);
  // The newest package available now or within `timeout`: skips queued older ones.
  std::optional<RtdeSample> ReceiveLatest(net::Milliseconds timeout);

  std::vector<rtde::TextMessage> TakeTextMessages();

  // V, v, O(frequency, outputs), S in one call; frequency 0 picks MaxFrequency().
  void Handshake(const std::vector<std::string>& outputs = RobotStateOutputs(),
                 double frequency = 0);

  int protocol_version() const { return protocol_version_; }
  const std::string& peer() const { return stream_.peer(); }
  const std::vector<std::string>& output_names() const { return output_names_; }

 private:
  void Send(rtde::PacketType type, const std::vector<uint8_t>& payload);
  // Waits for a reply of `type`, keeping data packages and text messages that come first.
  rtde::Packet AwaitReply(rtde::PacketType type, const std::string& step);
  // Reads more bytes into the framer; false on timeout.
  bool Fill(net::Milliseconds timeout);
  // Handles a packet that is not a reply; returns a sample for data packages.
  std::optional<RtdeSample> Absorb(const rtde::Packet& packet);
  std::string Where(const std::string& step) const;

  net::TcpStream stream_;
  net::Milliseconds timeout_;
  rtde::PacketFramer framer_;
  int protocol_version_ = 1;
  double max_frequency_ = kCb3MaxFrequency;
  uint8_t output_recipe_id_ = 0;
  std::vector<std::string> output_names_;
  std::vector<rtde::ValueType> output_types_;
  std::vector<std::vector<rtde::ValueType>> input_types_;  // by recipe id
  std::vector<RtdeSample> pending_samples_;
  std::vector<rtde::TextMessage> text_messages_;
};

}  // namespace avc::robot
