#include "drivers/robot/script_client.h"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

namespace avc::robot {
namespace {

using Clock = std::chrono::steady_clock;

}  // namespace

ScriptClient::ScriptClient(const std::string& host, uint16_t port, net::Milliseconds timeout)
    : stream_(net::TcpStream::Connect(host, port, timeout)), timeout_(timeout) {}

void ScriptClient::Send(const std::string& program) {
  std::string text = program;
  if (text.empty() || text.back() != '\n') text += '\n';
  try {
    stream_.SendAll(text, timeout_);
  } catch (const net::ConnectionError& error) {
    throw net::ConnectionError(fmt::format("secondary interface: send script: {}", error.what()));
  }
}

void ScriptClient::Absorb(primary::RobotStateMessage state) {
  ++robot_states_received_;
  if (state.mode) mode_ = state.mode;
  if (state.joints) joints_ = state.joints;
  if (state.cartesian) cartesian_ = state.cartesian;
  if (state.kinematics) kinematics_ = state.kinematics;
}

std::vector<primary::RobotMessage> ScriptClient::Poll(net::Milliseconds timeout) {
  std::vector<primary::RobotMessage> messages = std::exchange(unread_, {});
  const auto deadline = Clock::now() + timeout;
  while (true) {
    while (auto package = framer_.Next()) {
      if (package->type == primary::kRobotStateType) {
        Absorb(primary::DecodeRobotState(package->body));
        continue;
      }
      if (package->type != primary::kRobotMessageType) continue;
      if (auto message = primary::DecodeRobotMessage(package->body)) {
        messages.push_back(std::move(*message));
      } else if (auto version = primary::DecodeVersionMessage(package->body)) {
        version_ = std::move(version);
      }
    }
    if (!messages.empty()) return messages;
    const auto left = std::chrono::duration_cast<net::Milliseconds>(deadline - Clock::now());
    if (left.count() <= 0) return messages;
    uint8_t chunk[4096];
    size_t n = 0;
    try {
      n = stream_.ReceiveSome(chunk, sizeof(chunk), left);
    } catch (const net::ConnectionError& error) {
      throw net::ConnectionError(fmt::format("secondary interface: {}", error.what()));
    }
    if (n == 0) return messages;
    framer_.Append(chunk, n);
  }
}

std::optional<primary::KinematicsInfo> ScriptClient::WaitForKinematics(net::Milliseconds timeout) {
  const auto deadline = Clock::now() + timeout;
  while (!kinematics_) {
    const auto left = std::chrono::duration_cast<net::Milliseconds>(deadline - Clock::now());
    if (left.count() <= 0) break;
    for (auto& message : Poll(std::min(left, net::Milliseconds(20)))) {
      unread_.push_back(std::move(message));  // kept for the caller's next Poll
    }
  }
  return kinematics_;
}

}  // namespace avc::robot
