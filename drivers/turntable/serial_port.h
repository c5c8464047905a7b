#pragma once

// A serial line in raw 8N1 mode with non-blocking reads bounded by poll() timeouts. Works the
// same on /dev/ttyUSB*, /dev/ttyS* and a pseudo-terminal (the emulator), so the real backend is
// what the tests exercise.

#include <chrono>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "drivers/turntable/protocol/lt360_protocol.h"

namespace avc::turntable {

// The port cannot be opened or has gone away (unplugged adapter, closed pty).
class SerialError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class SerialPort {
 public:
  // Opens and configures path; throws SerialError naming the path and the reason, or
  // std::invalid_argument for a baud rate termios does not have.
  SerialPort(std::string path, int baud);
  ~SerialPort();
  SerialPort(const SerialPort&) = delete;
  SerialPort& operator=(const SerialPort&) = delete;

  const std::string& path() const { return path_; }
  int baud() const { return baud_; }

  // Writes text followed by terminator; throws SerialError on I/O failure or if the line stays
  // unwritable for timeout.
  void WriteLine(std::string_view text, char terminator, std::chrono::milliseconds timeout);
  // The next CR/NUL-terminated line, or nullopt when none completes within timeout. Throws
  // SerialError when the device reports hang-up or an I/O error.
  std::optional<std::string> ReadLine(std::chrono::milliseconds timeout);
  // Discards everything received but not yet read (kernel buffer and partial lines).
  void FlushInput();

 private:
  // Reads what is available without blocking into splitter_; false if nothing was there.
  bool ReadAvailable();

  std::string path_;
  int baud_;
  int fd_ = -1;
  FrameSplitter splitter_;
};

}  // namespace avc::turntable
