#include "sim/emulators/ur5/ur5_session.h"

#include <sys/socket.h>

#include <cerrno>
#include <exception>

namespace avc::sim::ur5 {

void Session::Queue(const std::vector<uint8_t>& bytes) {
  out_.insert(out_.end(), bytes.begin(), bytes.end());
}

void Session::Queue(const std::string& text) { out_.insert(out_.end(), text.begin(), text.end()); }

void Session::ReadAvailable() {
  uint8_t buffer[8192];
  while (!closed_) {
    const ssize_t n = recv(stream_.fd(), buffer, sizeof(buffer), 0);
    if (n == 0) {
      closed_ = true;
      return;
    }
    if (n < 0) {
      if (errno == EINTR) continue;
      if (errno != EAGAIN && errno != EWOULDBLOCK) closed_ = true;
      return;
    }
    try {
      Consume(buffer, static_cast<size_t>(n));
    } catch (const std::exception& error) {
      OnMalformed(error.what());
      Flush();
      closed_ = true;
    }
  }
}

void Session::Flush() {
  while (!out_.empty() && !closed_) {
    const ssize_t n = send(stream_.fd(), out_.data(), out_.size(), MSG_NOSIGNAL);
    if (n > 0) {
      out_.erase(out_.begin(), out_.begin() + n);
    } else if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
      return;
    } else if (n < 0 && errno == EINTR) {
      continue;
    } else {
      closed_ = true;
    }
  }
  if (hang_up_after_flush_ && out_.empty()) closed_ = true;
}

}  // namespace avc::sim::ur5
