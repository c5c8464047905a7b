#pragma once

// One accepted TCP connection of the PTP/IP camera: owns the socket, collects received bytes and
// cuts them into packets, and writes whole packets. Sends are blocking with a bound (SO_SNDTIMEO)
// so a client that stops reading cannot wedge the emulator thread forever.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "sim/emulators/ptpip/ptpip_packets.h"

namespace avc::sim::ptp {

enum class ConnectionRole { kUnknown, kCommand, kEvent };

class Connection {
 public:
  explicit Connection(int fd);
  ~Connection();
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;

  int fd() const { return fd_; }
  ConnectionRole role = ConnectionRole::kUnknown;
  uint32_t connection_number = 0;

  // Reads what the socket has; false when the peer closed or the socket failed.
  bool Receive();
  // Next whole packet, if any; throws PtpDecodeError on a corrupt header.
  std::optional<Packet> NextPacket() { return TakePacket(received_); }
  // False when the peer is gone or did not take the bytes in time.
  bool Send(std::span<const uint8_t> bytes);

 private:
  int fd_;
  std::vector<uint8_t> received_;
};

// Listening socket on 127.0.0.1:port (0 = ephemeral); returns the fd and the bound port.
// Throws std::runtime_error naming the port when it cannot listen.
int ListenLoopback(int port, int* bound_port);

}  // namespace avc::sim::ptp
