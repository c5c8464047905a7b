#include "core/net/tcp_socket.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <fmt/format.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace avc::net {
namespace {

using Clock = std::chrono::steady_clock;

void SetNonBlocking(int fd) {
  const int flags = fcntl(fd, F_GETFL, 0);
  fcntl(fd, F_SETFL, flags | O_NONBLOCK);
}

int RemainingMs(Clock::time_point deadline) {
  const auto left = std::chrono::duration_cast<Milliseconds>(deadline - Clock::now()).count();
  return left < 0 ? 0 : static_cast<int>(left);
}

// poll() on one fd, retrying on EINTR; true when `events` became ready.
bool WaitFor(int fd, short events, Clock::time_point deadline) {
  while (true) {
    pollfd entry{fd, events, 0};
    const int ready = poll(&entry, 1, RemainingMs(deadline));
    if (ready > 0) return true;
    if (ready == 0) return false;
    if (errno != EINTR) return false;
  }
}

}  // namespace

TcpStream TcpStream::Connect(const std::string& host, uint16_t port, Milliseconds timeout) {
  const std::string peer = fmt::format("{}:{}", host, port);
  addrinfo hints{};
  hints.ai_family = AF_INET;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  const int resolved = getaddrinfo(host.c_str(), std::to_string(port).c_str(), &hints, &found);
  if (resolved != 0 || found == nullptr) {
    throw ConnectionError(fmt::format("{}: cannot resolve host: {}", peer, gai_strerror(resolved)));
  }
  const int fd = socket(found->ai_family, found->ai_socktype | SOCK_CLOEXEC, found->ai_protocol);
  if (fd < 0) {
    freeaddrinfo(found);
    throw ConnectionError(fmt::format("{}: socket(): {}", peer, std::strerror(errno)));
  }
  TcpStream stream(fd, peer);
  SetNonBlocking(fd);
  const int one = 1;
  setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof(one));
  const int started = ::connect(fd, found->ai_addr, found->ai_addrlen);
  const int connect_errno = errno;
  freeaddrinfo(found);
  if (started != 0 && connect_errno != EINPROGRESS) {
    throw ConnectionError(fmt::format("{}: connect: {}", peer, std::strerror(connect_errno)));
  }
  if (started != 0) {
    if (!WaitFor(fd, POLLOUT, Clock::now() + timeout)) {
      throw ConnectionError(
          fmt::format("{}: connect timed out after {} ms", peer, timeout.count()));
    }
    int error = 0;
    socklen_t length = sizeof(error);
    getsockopt(fd, SOL_SOCKET, SO_ERROR, &error, &length);
    if (error != 0) {
      throw ConnectionError(fmt::format("{}: connect: {}", peer, std::strerror(error)));
    }
  }
  return stream;
}

TcpStream::TcpStream(TcpStream&& other) noexcept : fd_(other.fd_), peer_(std::move(other.peer_)) {
  other.fd_ = -1;
}

TcpStream& TcpStream::operator=(TcpStream&& other) noexcept {
  if (this != &other) {
    Close();
    fd_ = other.fd_;
    peer_ = std::move(other.peer_);
    other.fd_ = -1;
  }
  return *this;
}

void TcpStream::Close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

void TcpStream::SendAll(const void* data, size_t size, Milliseconds timeout) {
  if (fd_ < 0) throw ConnectionError(fmt::format("{}: send on a closed connection", peer_));
  const auto deadline = Clock::now() + timeout;
  const auto* bytes = static_cast<const uint8_t*>(data);
  size_t sent = 0;
  while (sent < size) {
    const ssize_t n = ::send(fd_, bytes + sent, size - sent, MSG_NOSIGNAL);
    if (n > 0) {
      sent += static_cast<size_t>(n);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
      if (!WaitFor(fd_, POLLOUT, deadline)) {
        throw ConnectionError(
            fmt::format("{}: send timed out after {} ms", peer_, timeout.count()));
      }
      continue;
    }
    throw ConnectionError(fmt::format("{}: send: {}", peer_, std::strerror(errno)));
  }
}

size_t TcpStream::ReceiveSome(uint8_t* buffer, size_t capacity, Milliseconds timeout) {
  if (fd_ < 0) throw ConnectionError(fmt::format("{}: receive on a closed connection", peer_));
  const auto deadline = Clock::now() + timeout;
  while (true) {
    const ssize_t n = ::recv(fd_, buffer, capacity, 0);
    if (n > 0) return static_cast<size_t>(n);
    if (n == 0) throw ConnectionError(fmt::format("{}: connection closed by peer", peer_));
    if (errno == EINTR) continue;
    if (errno != EAGAIN && errno != EWOULDBLOCK) {
      throw ConnectionError(fmt::format("{}: receive: {}", peer_, std::strerror(errno)));
    }
    if (!WaitFor(fd_, POLLIN, deadline)) return 0;
  }
}

TcpListener::TcpListener(const std::string& host, uint16_t port) {
  fd_ = socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd_ < 0) throw ConnectionError(fmt::format("listen socket: {}", std::strerror(errno)));
  const int one = 1;
  setsockopt(fd_, SOL_SOCKET, SO_REUSEADDR, &one, sizeof(one));
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(port);
  if (inet_pton(AF_INET, host.c_str(), &address.sin_addr) != 1) {
    ::close(fd_);
    throw ConnectionError(fmt::format("listen {}:{}: not an IPv4 address", host, port));
  }
  if (bind(fd_, reinterpret_cast<sockaddr*>(&address), sizeof(address)) != 0 ||
      listen(fd_, 8) != 0) {
    const int error = errno;
    ::close(fd_);
    throw ConnectionError(fmt::format("listen {}:{}: {}", host, port, std::strerror(error)));
  }
  socklen_t length = sizeof(address);
  getsockname(fd_, reinterpret_cast<sockaddr*>(&address), &length);
  port_ = ntohs(address.sin_port);
  SetNonBlocking(fd_);
}

TcpListener::~TcpListener() {
  if (fd_ >= 0) ::close(fd_);
}

TcpStream TcpListener::Accept() {
  sockaddr_in address{};
  socklen_t length = sizeof(address);
  const int fd = ::accept4(fd_, reinterpret_cast<sockaddr*>(&address), &length, SOCK_CLOEXEC);
  if (fd < 0) return {};
  SetNonBlocking(fd);
  const int one = 1;
  setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof(one));
  char text[INET_ADDRSTRLEN] = {};
  inet_ntop(AF_INET, &address.sin_addr, text, sizeof(text));
  return TcpStream(fd, fmt::format("{}:{}", text, ntohs(address.sin_port)));
}

}  // namespace avc::net
