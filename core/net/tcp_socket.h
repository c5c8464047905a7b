#pragma once

// Minimal non-blocking TCP for the UR interfaces: every wait goes through poll() with a timeout,
// and every error names the peer (host:port) so a failure says which interface broke.

#include <chrono>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace avc::net {

// The peer closed the connection or the socket failed; what() names host:port.
class ConnectionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

using Milliseconds = std::chrono::milliseconds;

class TcpStream {
 public:
  // Connects within `timeout`; throws ConnectionError naming host:port and the cause.
  static TcpStream Connect(const std::string& host, uint16_t port, Milliseconds timeout);
  // Adopts an accepted, already non-blocking socket.
  TcpStream(int fd, std::string peer) : fd_(fd), peer_(std::move(peer)) {}
  TcpStream() = default;
  TcpStream(TcpStream&& other) noexcept;
  TcpStream& operator=(TcpStream&& other) noexcept;
  TcpStream(const TcpStream&) = delete;
  TcpStream& operator=(const TcpStream&) = delete;
  ~TcpStream() { Close(); }

  // Writes every byte within `timeout`; throws ConnectionError otherwise.
  void SendAll(const void* data, size_t size, Milliseconds timeout);
  void SendAll(const std::string& text, Milliseconds timeout) {
    SendAll(text.data(), text.size(), timeout);
  }
  // Waits up to `timeout` for data and reads what is there (at most `capacity`); 0 means the
  // wait timed out. Throws ConnectionError when the peer closed the connection.
  size_t ReceiveSome(uint8_t* buffer, size_t capacity, Milliseconds timeout);

  bool is_open() const { return fd_ >= 0; }
  int fd() const { return fd_; }
  const std::string& peer() const { return peer_; }
  void Close();

 private:
  int fd_ = -1;
  std::string peer_;
};

// A listening socket on 127.0.0.1 (or `host`); port 0 picks an ephemeral port.
class TcpListener {
 public:
  TcpListener(const std::string& host, uint16_t port);
  TcpListener(const TcpListener&) = delete;
  TcpListener& operator=(const TcpListener&) = delete;
  ~TcpListener();

  uint16_t port() const { return port_; }
  int fd() const { return fd_; }
  // A pending connection as a non-blocking stream, or a closed stream when none is pending.
  TcpStream Accept();

 private:
  int fd_ = -1;
  uint16_t port_ = 0;
};

}  // namespace avc::net
