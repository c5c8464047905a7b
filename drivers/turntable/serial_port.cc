#include "drivers/turntable/serial_port.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "core/util/clock.h"

namespace avc::turntable {
namespace {

speed_t BaudConstant(int baud) {
  switch (baud) {
    case 1200:
      return B1200;
    case 2400:
      return B2400;
    case 4800:
      return B4800;
    case 9600:
      return B9600;
    case 19200:
      return B19200;
    case 38400:
      return B38400;
    case 57600:
      return B57600;
    case 115200:
      return B115200;
    case 230400:
      return B230400;
    default:
      throw std::invalid_argument(fmt::format(
          "unsupported baud rate {} (use 1200, 2400, 4800, 9600, 19200, 38400, 57600, 115200 or "
          "230400)",
          baud));
  }
}

std::string ErrnoText() { return std::strerror(errno); }

int RemainingMs(int64_t deadline_us) {
  const int64_t left = deadline_us - MonotonicMicros();
  return left <= 0 ? 0 : static_cast<int>((left + 999) / 1000);
}

}  // namespace

SerialPort::SerialPort(std::string path, int baud) : path_(std::move(path)), baud_(baud) {
  const speed_t speed = BaudConstant(baud);
  fd_ = ::open(path_.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd_ < 0) throw SerialError(fmt::format("cannot open {}: {}", path_, ErrnoText()));
  termios tio{};
  if (::tcgetattr(fd_, &tio) != 0) {
    const std::string why = ErrnoText();
    ::close(fd_);
    throw SerialError(fmt::format("{} is not a serial port: {}", path_, why));
  }
  ::cfmakeraw(&tio);  // 8 data bits, no parity, no echo, no line editing
  tio.c_cflag &= ~(CSTOPB | CRTSCTS);
  tio.c_cflag |= CLOCAL | CREAD;
  tio.c_cc[VMIN] = 0;
  tio.c_cc[VTIME] = 0;
  ::cfsetispeed(&tio, speed);
  ::cfsetospeed(&tio, speed);
  if (::tcsetattr(fd_, TCSANOW, &tio) != 0) {
    const std::string why = ErrnoText();
    ::close(fd_);
    throw SerialError(fmt::format("cannot configure {} as 8N1 at {} baud: {}", path_, baud, why));
  }
  ::tcflush(fd_, TCIOFLUSH);
}

SerialPort::~SerialPort() {
  if (fd_ >= 0) ::close(fd_);
}

void SerialPort::WriteLine(std::string_view text, char terminator,
                           std::chrono::milliseconds timeout) {
  std::string bytes(text);
  bytes += terminator;
  const int64_t deadline = MonotonicMicros() + timeout.count() * 1000;
  size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd_, bytes.data() + written, bytes.size() - written);
    if (n > 0) {
      written += static_cast<size_t>(n);
      continue;
    }
    if (n < 0 && errno != EAGAIN && errno != EINTR) {
      throw SerialError(fmt::format("write to {} failed: {}", path_, ErrnoText()));
    }
    pollfd pfd{fd_, POLLOUT, 0};
    const int ready = ::poll(&pfd, 1, RemainingMs(deadline));
    if (ready == 0) {
      throw SerialError(fmt::format("{} stayed unwritable for {} ms", path_, timeout.count()));
    }
    if (ready > 0 && (pfd.revents & (POLLERR | POLLHUP | POLLNVAL))) {
      throw SerialError(fmt::format("{} hung up while writing", path_));
    }
  }
}

bool SerialPort::ReadAvailable() {
  char buffer[256];
  bool any = false;
  while (true) {
    const ssize_t n = ::read(fd_, buffer, sizeof(buffer));
    if (n > 0) {
      splitter_.Feed(std::string_view(buffer, static_cast<size_t>(n)));
      any = true;
      continue;
    }
    if (n < 0 && (errno == EAGAIN || errno == EINTR)) return any;
    // 0 bytes on a non-blocking tty with VMIN=0 means nothing to read; EIO means hang-up.
    if (n == 0) return any;
    throw SerialError(fmt::format("read from {} failed: {}", path_, ErrnoText()));
  }
}

std::optional<std::string> SerialPort::ReadLine(std::chrono::milliseconds timeout) {
  const int64_t deadline = MonotonicMicros() + timeout.count() * 1000;
  while (true) {
    if (std::optional<std::string> line = splitter_.Next()) return line;
    const int wait_ms = RemainingMs(deadline);
    pollfd pfd{fd_, POLLIN, 0};
    const int ready = ::poll(&pfd, 1, wait_ms);
    if (ready < 0 && errno != EINTR) {
      throw SerialError(fmt::format("poll on {} failed: {}", path_, ErrnoText()));
    }
    if (ready > 0) {
      if (pfd.revents & POLLIN) ReadAvailable();
      if (pfd.revents & (POLLERR | POLLHUP | POLLNVAL)) {
        if (std::optional<std::string> line = splitter_.Next()) return line;
        throw SerialError(fmt::format("{} hung up (device disconnected?)", path_));
      }
    }
    if (wait_ms == 0) return splitter_.Next();
  }
}

void SerialPort::FlushInput() {
  ::tcflush(fd_, TCIFLUSH);
  ReadAvailable();
  splitter_.Clear();
}

}  // namespace avc::turntable
