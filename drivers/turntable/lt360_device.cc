#include "drivers/turntable/lt360_device.h"

#include <fmt/format.h>

#include <cctype>

namespace avc::turntable {
namespace {

std::string Seconds(std::chrono::milliseconds duration) {
  return duration.count() % 1000 == 0 ? fmt::format("{} s", duration.count() / 1000)
                                      : fmt::format("{:.3g} s", duration.count() / 1000.0);
}

}  // namespace

int NormaliseTenths(int tenths) { return ((tenths % 3600) + 3600) % 3600; }

Lt360Device::Lt360Device(std::unique_ptr<SerialPort> port, DeviceOptions options)
    : port_(std::move(port)), options_(std::move(options)) {
  if (!port_) throw std::invalid_argument("Lt360Device needs a serial port");
  const std::string problem = options_.table.Validate();
  if (!problem.empty()) throw ProtocolError(problem);
  if (options_.command_timeout.count() <= 0 || options_.invalid_reply_retries < 0) {
    throw std::invalid_argument("Lt360Device: command timeout must be > 0 and retries >= 0");
  }
}

template <class Parse>
auto Lt360Device::Transact(const std::string& command, Retry retry, Parse parse) {
  const int attempts = retry == Retry::kAllowed ? 1 + options_.invalid_reply_retries : 1;
  for (int attempt = 1;; ++attempt) {
    // Stale bytes (a late reply to a timed-out command) must not be read as this reply.
    port_->FlushInput();
    ++stats_.commands;
    port_->WriteLine(command, options_.terminator, options_.command_timeout);
    const std::optional<std::string> reply = port_->ReadLine(options_.command_timeout);
    if (!reply) {
      ++stats_.timeouts;
      port_->FlushInput();
      throw SerialTimeout(fmt::format("serial timeout after {} waiting for reply to '{}' on {}",
                                      Seconds(options_.command_timeout), command, port_->path()));
    }
    if (!options_.table.error_reply.empty() &&
        EqualsIgnoreCase(*reply, options_.table.error_reply)) {
      throw ProtocolError(fmt::format("the turntable on {} rejected '{}' (replied '{}')",
                                      port_->path(), command, *reply));
    }
    try {
      return parse(*reply);
    } catch (const InvalidReply& e) {
      ++stats_.invalid_replies;
      if (attempt >= attempts) {
        throw InvalidReply(fmt::format("{} to '{}' on {} (after {} attempt{})", e.what(), command,
                                       port_->path(), attempt, attempt == 1 ? "" : "s"));
      }
    }
  }
}

int Lt360Device::PositionTenths() {
  const std::string command = FormatCommand(options_.table, CommandKind::kGetPosition);
  return NormaliseTenths(Transact(command, Retry::kAllowed, ParsePositionTenths));
}

Motion Lt360Device::Moving() {
  const std::string command = FormatCommand(options_.table, CommandKind::kGetMoving);
  return Transact(command, Retry::kAllowed, ParseMotion);
}

void Lt360Device::Action(CommandKind kind, double value, Retry retry) {
  const std::string command = FormatCommand(options_.table, kind, value);
  const std::string& expected = options_.table.done_reply;
  if (expected.empty()) {
    port_->FlushInput();
    ++stats_.commands;
    port_->WriteLine(command, options_.terminator, options_.command_timeout);
    return;
  }
  Transact(command, retry, [&](const std::string& reply) {
    if (!EqualsIgnoreCase(reply, expected)) {
      throw InvalidReply(fmt::format("invalid reply '{}' (expected '{}')", reply, expected));
    }
    return 0;
  });
}

void Lt360Device::Goto(int tenths, Direction direction) {
  const CommandKind kind = direction == Direction::kCw    ? CommandKind::kGotoCw
                           : direction == Direction::kCcw ? CommandKind::kGotoCcw
                                                          : CommandKind::kGotoShortest;
  Action(kind, NormaliseTenths(tenths) / 10.0, Retry::kAllowed);
}

void Lt360Device::Step(int tenths) { Action(CommandKind::kStep, tenths / 10.0, Retry::kNever); }

void Lt360Device::Home() { Action(CommandKind::kHome, 0, Retry::kAllowed); }

void Lt360Device::Stop() { Action(CommandKind::kStop, 0, Retry::kAllowed); }

void Lt360Device::SetSpeed(double deg_per_s) {
  if (!(deg_per_s > 0)) {
    throw std::invalid_argument(
        fmt::format("turntable speed must be > 0 deg/s, got {}", deg_per_s));
  }
  Action(CommandKind::kSetSpeed, deg_per_s, Retry::kAllowed);
}

int Lt360Device::Recover() {
  port_->FlushInput();
  return PositionTenths();
}

}  // namespace avc::turntable
