#pragma once

// One LT360 on a serial port: each call sends one command from the table and waits for its
// reply. Errors name the command, the reply and the port, e.g. "serial timeout after 10 s waiting
// for reply to 'CP' on /dev/pts/3". Invalid replies are retried (bounded) where repeating the
// command is harmless; a relative step is never repeated.

#include <chrono>
#include <memory>
#include <stdexcept>
#include <string>

#include "drivers/turntable/protocol/lt360_protocol.h"
#include "drivers/turntable/serial_port.h"

namespace avc::turntable {

// No reply within the command timeout. The port is flushed before this is thrown, so the next
// command starts clean.
class SerialTimeout : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Angles grow counter-clockwise seen from above (math-positive about the table axis), so CW
// motion decreases the reported angle and a positive step turns CCW.
enum class Direction { kShortest, kCw, kCcw };

struct DeviceOptions {
  CommandTable table;
  // The LT360 itself gives up on a command after 10 s without terminator.
  std::chrono::milliseconds command_timeout{10'000};
  // Extra attempts after an invalid reply to a repeatable command.
  int invalid_reply_retries = 2;
  char terminator = '\r';
};

struct DeviceStats {
  int64_t commands = 0;
  int64_t invalid_replies = 0;
  int64_t timeouts = 0;
};

class Lt360Device {
 public:
  // Throws ProtocolError when the options' table is invalid.
  Lt360Device(std::unique_ptr<SerialPort> port, DeviceOptions options);

  const std::string& port_path() const { return port_->path(); }
  const DeviceOptions& options() const { return options_; }
  const DeviceStats& stats() const { return stats_; }

  // The position in tenths of a degree, normalised to [0, 3600).
  int PositionTenths();
  Motion Moving();
  // Absolute move to tenths (any value; normalised to [0, 3600)). Throws ProtocolError when the
  // table has no command for that direction.
  void Goto(int tenths, Direction direction);
  // Relative move by signed tenths.
  void Step(int tenths);
  void Home();
  void Stop();
  void SetSpeed(double deg_per_s);
  // After a timeout or garbage: drop stale input and check the device answers again.
  int Recover();

 private:
  enum class Retry { kAllowed, kNever };
  // Sends the command and returns the reply; throws SerialTimeout, InvalidReply (after the
  // retries) or SerialError.
  template <class Parse>
  auto Transact(const std::string& command, Retry retry, Parse parse);
  void Action(CommandKind kind, double value, Retry retry);

  std::unique_ptr<SerialPort> port_;
  DeviceOptions options_;
  DeviceStats stats_;
};

// tenths mod 3600 into [0, 3600).
int NormaliseTenths(int tenths);

}  // namespace avc::turntable
