#pragma once

// One client connection of the emulated controller, whatever the interface: the non-blocking
// socket, its output queue (bounded by the interfaces that stream), reading what arrived and
// handing it to the interface, and hanging up. Interfaces derive from it (ur5_rtde_server.h,
// ur5_primary_server.h, ur5_dashboard_server.h).

#include <cstdint>
#include <string>
#include <vector>

#include "core/net/tcp_socket.h"

namespace avc::sim::ur5 {

// Output bytes a slow client may have queued before streamed state is dropped (coalescing: it
// then gets the newest state when it catches up, and the queue never grows without bound).
inline constexpr size_t kMaxQueuedBytes = 64 * 1024;

class Session {
 public:
  Session(int id, net::TcpStream stream) : id_(id), stream_(std::move(stream)) {}
  virtual ~Session() = default;
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  int id() const { return id_; }
  int fd() const { return stream_.fd(); }
  bool closed() const { return closed_; }
  bool wants_write() const { return !out_.empty(); }

  // Reads everything available and hands it to Consume. The peer hanging up closes the session;
  // so does a malformed stream (after OnMalformed had its say: the stream cannot resync).
  void ReadAvailable();
  // Sends what the socket takes now; a session asked to hang up closes once its queue is out.
  void Flush();
  // Marks the session closed; the emulator drops it.
  void Close() { closed_ = true; }

  // Runs after every control tick (streams state).
  virtual void OnTick() {}

  void Queue(const std::vector<uint8_t>& bytes);
  void Queue(const std::string& text);
  size_t queued() const { return out_.size(); }

 protected:
  // Bytes from the client; throws std::exception on malformed input.
  virtual void Consume(const uint8_t* data, size_t size) = 0;
  // Called with the error before a malformed stream is closed.
  virtual void OnMalformed(const std::string& /*what*/) {}
  void HangUpAfterFlush() { hang_up_after_flush_ = true; }

 private:
  int id_;
  net::TcpStream stream_;
  std::vector<uint8_t> out_;
  bool closed_ = false;
  bool hang_up_after_flush_ = false;
};

}  // namespace avc::sim::ur5
