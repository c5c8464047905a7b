#pragma once

// A PTP/IP camera on 127.0.0.1 that stock libgphoto2 (ptp2 camlib, model "PTP/IP Camera",
// port "ptpip:127.0.0.1:PORT") opens, configures, captures from, downloads from and deletes on
// One thread serves the listener, the command/data connection and the
// event connection with poll(). Generic PTP only: no vendor extension, no live view.
//
// A capture runs like a camera's: InitiateCapture is answered at once, the frame source renders
// the shot, the clock waits out the capture latency (exposure + card write), then ObjectAdded and
// CaptureComplete go out on the event connection. While it waits the camera answers nothing,
// as a busy body would not. A capture refused with DeviceBusy is followed by a CaptureComplete
// without ObjectAdded: stock libgphoto2 2.5.30 otherwise waits for capture events forever after
// logging the busy answer (its generic capture loop has no deadline before CaptureComplete).

#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "sim/emulators/clock/emulator_clock.h"
#include "sim/emulators/ptpip/emulated_capture.h"
#include "sim/emulators/ptpip/ptp_responder.h"
#include "sim/emulators/ptpip/ptpip_connection.h"

namespace avc::sim {

struct PtpIpCameraOptions {
  int port = 0;  // 0 = ephemeral; port() tells which
  FrameSource frame_source;
  double capture_latency_s = 0;  // simulated seconds from InitiateCapture to ObjectAdded
  ptp::DeviceIdentity identity;

  // Empty when usable, else what is wrong.
  std::string Validate() const;
};

// Who connected last (from its InitCommandRequest).
struct PtpIpClient {
  ptp::Guid guid{};
  std::string host_name;
  uint32_t version = 0;
};

class PtpIpCamera {
 public:
  // Listens and starts serving. Throws std::invalid_argument for bad options and
  // std::runtime_error when it cannot listen. clock defaults to real time.
  explicit PtpIpCamera(PtpIpCameraOptions options, std::shared_ptr<EmulatorClock> clock = nullptr);
  ~PtpIpCamera();
  PtpIpCamera(const PtpIpCamera&) = delete;
  PtpIpCamera& operator=(const PtpIpCamera&) = delete;

  int port() const { return port_; }
  // "ptpip:127.0.0.1:PORT:PORT" for libgphoto2. The event port must be spelled out: with
  // "ptpip:HOST:PORT" libgphoto2 2.5.30 opens the event connection on 15740 regardless.
  std::string libgphoto2_port() const;
  // Stops serving and closes every socket; idempotent.
  void Stop();

  // The next `count` InitiateCapture requests answer DeviceBusy (0x2019).
  void InjectBusy(int count);
  // Closes the client's connections (as a camera switched off would) but keeps listening so a
  // client can connect again. Returns once the sockets are closed.
  void DropConnections();

  int64_t captures() const;        // accepted InitiateCaptures whose image was stored
  int64_t objects_stored() const;  // images on the card now
  int64_t sessions_opened() const;
  int64_t unsupported_requests() const;  // requests answered OperationNotSupported
  EmulatedSettings settings() const;
  std::optional<PtpIpClient> client() const;

 private:
  void Serve();
  void Accept();
  // Handles every whole packet a connection has; false when it must be closed.
  bool HandlePackets(ptp::Connection& connection);
  bool HandleHandshake(ptp::Connection& connection, const ptp::Packet& packet);
  bool HandleCommand(ptp::Connection& connection, const ptp::Packet& packet);
  bool RunOperation(const ptp::OperationRequest& request, const std::vector<uint8_t>& data_in);
  bool SendData(uint32_t transaction_id, const std::vector<uint8_t>& data);
  void RunCapture(uint32_t transaction_id);
  void SendEvent(uint16_t code, uint32_t transaction_id, std::vector<uint32_t> params);
  void CloseConnection(ptp::Connection* connection);
  void CloseClient();
  void Wake();

  PtpIpCameraOptions options_;
  std::shared_ptr<EmulatorClock> clock_;
  int listen_fd_ = -1;
  int wake_fd_ = -1;  // eventfd: Stop() and DropConnections() requests
  int port_ = 0;

  // Owned by the serving thread.
  std::vector<std::unique_ptr<ptp::Connection>> connections_;
  ptp::Connection* command_ = nullptr;
  ptp::Connection* event_ = nullptr;
  uint32_t next_connection_number_ = 1;
  struct PendingDataOut {
    ptp::OperationRequest request;
    std::vector<uint8_t> data;
    uint64_t expected = 0;
    bool started = false;
  };
  std::optional<PendingDataOut> pending_;

  mutable std::mutex mutex_;  // guards what tests read and request
  std::condition_variable drop_done_;
  ptp::PtpResponder responder_;
  std::optional<PtpIpClient> client_;
  int64_t captures_ = 0;
  int64_t unsupported_requests_ = 0;
  bool stop_requested_ = false;
  int64_t drops_requested_ = 0;
  int64_t drops_done_ = 0;
  std::thread thread_;
};

}  // namespace avc::sim
