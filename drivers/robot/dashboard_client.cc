#include "drivers/robot/dashboard_client.h"

#include <fmt/format.h>

#include <stdexcept>

#include "core/util/trim.h"

namespace avc::robot {
namespace {

using Clock = std::chrono::steady_clock;

}  // namespace

std::string ReplyValue(const std::string& reply, std::string_view prefix) {
  const std::string head = std::string(prefix) + ":";
  if (reply.compare(0, head.size(), head) != 0) {
    throw std::runtime_error(
        fmt::format("dashboard reply '{}' does not start with '{}'", reply, head));
  }
  return std::string(TrimSpace(std::string_view(reply).substr(head.size())));
}

DashboardClient::DashboardClient(const std::string& host, uint16_t port, net::Milliseconds timeout)
    : stream_(net::TcpStream::Connect(host, port, timeout)), timeout_(timeout) {
  banner_ = ReadLine("banner");
  if (banner_.rfind(kDashboardBanner, 0) != 0) {
    throw std::runtime_error(
        fmt::format("dashboard {}: unexpected banner '{}'", stream_.peer(), banner_));
  }
}

void DashboardClient::CheckConnected() {
  uint8_t chunk[1024];
  try {
    const size_t n = stream_.ReceiveSome(chunk, sizeof(chunk), net::Milliseconds(0));
    buffer_.append(reinterpret_cast<const char*>(chunk), n);
  } catch (const net::ConnectionError& error) {
    throw net::ConnectionError(fmt::format("dashboard: {}", error.what()));
  }
}

std::string DashboardClient::ReadLine(const std::string& step) {
  const auto deadline = Clock::now() + timeout_;
  while (true) {
    const size_t end = buffer_.find('\n');
    if (end != std::string::npos) {
      std::string line = std::string(TrimSpace(std::string_view(buffer_).substr(0, end)));
      buffer_.erase(0, end + 1);
      return line;
    }
    const auto left = std::chrono::duration_cast<net::Milliseconds>(deadline - Clock::now());
    uint8_t chunk[1024];
    size_t n = 0;
    try {
      n = left.count() > 0 ? stream_.ReceiveSome(chunk, sizeof(chunk), left) : 0;
    } catch (const net::ConnectionError& error) {
      throw net::ConnectionError(fmt::format("dashboard {}: {}", step, error.what()));
    }
    if (n == 0) {
      throw std::runtime_error(fmt::format("dashboard {}: {}: no reply within {} ms",
                                           stream_.peer(), step, timeout_.count()));
    }
    buffer_.append(reinterpret_cast<const char*>(chunk), n);
  }
}

std::string DashboardClient::Command(const std::string& command) {
  if (command.find('\n') != std::string::npos) {
    throw std::invalid_argument(
        fmt::format("dashboard command '{}' must be a single line", command));
  }
  try {
    stream_.SendAll(command + "\n", timeout_);
  } catch (const net::ConnectionError& error) {
    throw net::ConnectionError(fmt::format("dashboard '{}': {}", command, error.what()));
  }
  return ReadLine("'" + command + "'");
}

std::string DashboardClient::Expect(const std::string& command, std::string_view expected) {
  const std::string reply = Command(command);
  if (reply.rfind(expected, 0) != 0) {
    throw std::runtime_error(fmt::format("dashboard {}: '{}' answered '{}', expected '{}'",
                                         stream_.peer(), command, reply, expected));
  }
  return reply;
}

void DashboardClient::PowerOn() { Expect("power on", "Powering on"); }
void DashboardClient::PowerOff() { Expect("power off", "Powering off"); }
void DashboardClient::BrakeRelease() { Expect("brake release", "Brake releasing"); }
void DashboardClient::UnlockProtectiveStop() {
  Expect("unlock protective stop", "Protective stop releasing");
}
void DashboardClient::CloseSafetyPopup() { Expect("close safety popup", "closing safety popup"); }

RobotMode DashboardClient::GetRobotMode() {
  const std::string value = ReplyValue(Command("robotmode"), "Robotmode");
  const auto mode = ParseRobotMode(value);
  if (!mode) {
    throw std::runtime_error(
        fmt::format("dashboard {}: unknown robot mode '{}'", stream_.peer(), value));
  }
  return *mode;
}

SafetyMode DashboardClient::GetSafetyMode() {
  const std::string value = ReplyValue(Command("safetymode"), "Safetymode");
  const auto mode = ParseSafetyMode(value);
  if (!mode) {
    throw std::runtime_error(
        fmt::format("dashboard {}: unknown safety mode '{}'", stream_.peer(), value));
  }
  return *mode;
}

std::string DashboardClient::SafetyStatus() {
  return ReplyValue(Command("safetystatus"), "Safetystatus");
}

std::string DashboardClient::PolyscopeVersion() { return Expect("PolyscopeVersion", "URSoftware"); }

}  // namespace avc::robot
