#include "sim/emulators/ptpip/ptpip_camera.h"

#include <fmt/format.h>
#include <poll.h>
#include <sys/eventfd.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "core/util/log.h"
#include "sim/emulators/ptpip/byte_io.h"
#include "sim/emulators/ptpip/ptp_codes.h"

namespace avc::sim {
namespace {

using ptp::Connection;
using ptp::ConnectionRole;
using ptp::Packet;
using ptp::PacketType;

// Image data goes out in Data packets of this size (libgphoto2 accepts any size).
constexpr size_t kDataChunkBytes = 64 * 1024;
// The emulator's own GUID and the name it answers InitCommandRequest with.
constexpr ptp::Guid kCameraGuid = {0x41, 0x56, 0x43, 0x2d, 0x50, 0x54, 0x50, 0x49,
                                   0x50, 0x2d, 0x45, 0x4d, 0x55, 0x00, 0x00, 0x01};

}  // namespace

std::string PtpIpCameraOptions::Validate() const {
  if (port < 0 || port > 65535) return fmt::format("port {} outside [0, 65535]", port);
  if (!frame_source) return "frame_source is not set";
  if (!(capture_latency_s >= 0) || capture_latency_s > 3600) {
    return fmt::format("capture_latency_s {} outside [0, 3600]", capture_latency_s);
  }
  return "";
}

PtpIpCamera::PtpIpCamera(PtpIpCameraOptions options, std::shared_ptr<EmulatorClock> clock)
    : options_(std::move(options)),
      clock_(clock ? std::move(clock) : std::make_shared<RealTimeEmulatorClock>()),
      responder_(options_.identity) {
  if (const std::string problem = options_.Validate(); !problem.empty()) {
    throw std::invalid_argument("PTP/IP camera options: " + problem);
  }
  listen_fd_ = ptp::ListenLoopback(options_.port, &port_);
  wake_fd_ = eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK);
  if (wake_fd_ < 0) {
    close(listen_fd_);
    throw std::runtime_error(fmt::format("PTP/IP camera: eventfd: {}", std::strerror(errno)));
  }
  thread_ = std::thread([this] { Serve(); });
}

PtpIpCamera::~PtpIpCamera() { Stop(); }

void PtpIpCamera::Stop() {
  {
    std::lock_guard lock(mutex_);
    stop_requested_ = true;
  }
  if (thread_.joinable()) {
    Wake();
    thread_.join();
  }
  connections_.clear();
  command_ = event_ = nullptr;
  if (listen_fd_ >= 0) close(listen_fd_);
  if (wake_fd_ >= 0) close(wake_fd_);
  listen_fd_ = wake_fd_ = -1;
}

void PtpIpCamera::Wake() {
  const uint64_t one = 1;
  [[maybe_unused]] const ssize_t n = write(wake_fd_, &one, sizeof(one));
}

void PtpIpCamera::InjectBusy(int count) {
  std::lock_guard lock(mutex_);
  responder_.InjectBusy(count);
}

void PtpIpCamera::DropConnections() {
  std::unique_lock lock(mutex_);
  if (!thread_.joinable() || stop_requested_) return;
  const int64_t ticket = ++drops_requested_;
  Wake();
  drop_done_.wait(lock, [&] { return drops_done_ >= ticket || stop_requested_; });
}

int64_t PtpIpCamera::captures() const {
  std::lock_guard lock(mutex_);
  return captures_;
}

int64_t PtpIpCamera::objects_stored() const {
  std::lock_guard lock(mutex_);
  return static_cast<int64_t>(responder_.store().size());
}

int64_t PtpIpCamera::sessions_opened() const {
  std::lock_guard lock(mutex_);
  return responder_.sessions_opened();
}

int64_t PtpIpCamera::unsupported_requests() const {
  std::lock_guard lock(mutex_);
  return unsupported_requests_;
}

EmulatedSettings PtpIpCamera::settings() const {
  std::lock_guard lock(mutex_);
  return responder_.settings();
}

std::string PtpIpCamera::libgphoto2_port() const {
  return fmt::format("ptpip:127.0.0.1:{}:{}", port_, port_);
}

std::optional<PtpIpClient> PtpIpCamera::client() const {
  std::lock_guard lock(mutex_);
  return client_;
}

void PtpIpCamera::Serve() {
  while (true) {
    int64_t drop_target = 0;
    {
      std::lock_guard lock(mutex_);
      if (stop_requested_) break;
      drop_target = drops_requested_ > drops_done_ ? drops_requested_ : 0;
    }
    if (drop_target > 0) {
      CloseClient();
      std::lock_guard lock(mutex_);
      drops_done_ = drop_target;
      drop_done_.notify_all();
    }
    std::vector<pollfd> fds;
    fds.push_back({wake_fd_, POLLIN, 0});
    fds.push_back({listen_fd_, POLLIN, 0});
    for (const auto& connection : connections_) fds.push_back({connection->fd(), POLLIN, 0});
    if (poll(fds.data(), fds.size(), -1) < 0) {
      if (errno == EINTR) continue;
      log::Error("PTP/IP camera: poll: {}", std::strerror(errno));
      break;
    }
    if (fds[0].revents != 0) {
      uint64_t count = 0;
      [[maybe_unused]] const ssize_t n = read(wake_fd_, &count, sizeof(count));
    }
    if (fds[1].revents & POLLIN) Accept();
    // Collect first: handling may close connections (and so change connections_).
    std::vector<Connection*> ready;
    for (size_t i = 2; i < fds.size(); ++i) {
      if (fds[i].revents == 0) continue;
      for (const auto& connection : connections_) {
        if (connection->fd() == fds[i].fd) ready.push_back(connection.get());
      }
    }
    for (Connection* connection : ready) {
      const bool still_open = std::any_of(connections_.begin(), connections_.end(),
                                          [&](const auto& c) { return c.get() == connection; });
      if (!still_open) continue;
      if (!connection->Receive() || !HandlePackets(*connection)) {
        log::Debug("PTP/IP camera: closing fd {}", connection->fd());
        CloseConnection(connection);
      }
    }
  }
  std::lock_guard lock(mutex_);
  drop_done_.notify_all();
}

void PtpIpCamera::Accept() {
  const int fd = accept4(listen_fd_, nullptr, nullptr, SOCK_CLOEXEC);
  if (fd < 0) return;
  connections_.push_back(std::make_unique<Connection>(fd));
  log::Debug("PTP/IP camera: accepted fd {}", fd);
}

bool PtpIpCamera::HandlePackets(Connection& connection) {
  try {
    while (std::optional<Packet> packet = connection.NextPacket()) {
      bool keep = true;
      if (packet->type == PacketType::kPing) {
        keep = connection.Send(ptp::EncodePong());
      } else if (connection.role == ConnectionRole::kUnknown) {
        keep = HandleHandshake(connection, *packet);
      } else if (connection.role == ConnectionRole::kCommand) {
        keep = HandleCommand(connection, *packet);
      } else {
        log::Debug("PTP/IP camera: ignoring {} on the event connection",
                   ptp::PacketTypeName(packet->type));
      }
      if (!keep) return false;
    }
  } catch (const ptp::PtpDecodeError& e) {
    log::Warn("PTP/IP camera: closing connection after a corrupt packet: {}", e.what());
    return false;
  }
  return true;
}

bool PtpIpCamera::HandleHandshake(Connection& connection, const Packet& packet) {
  if (packet.type == PacketType::kInitCommandRequest) {
    const ptp::InitCommandRequest request = ptp::DecodeInitCommandRequest(packet.payload);
    // One client at a time: a new one means the old one is gone (crashed, re-initialising).
    log::Debug("PTP/IP camera: InitCommandRequest on fd {}", connection.fd());
    if (command_ != nullptr) CloseClient();
    connection.role = ConnectionRole::kCommand;
    connection.connection_number = next_connection_number_++;
    command_ = &connection;
    {
      std::lock_guard lock(mutex_);
      client_ = PtpIpClient{request.guid, request.host_name, request.version};
    }
    ptp::InitCommandAck ack{connection.connection_number, kCameraGuid, options_.identity.model,
                            ptp::kPtpIpVersion};
    return connection.Send(ptp::Encode(ack));
  }
  if (packet.type == PacketType::kInitEventRequest) {
    const ptp::InitEventRequest request = ptp::DecodeInitEventRequest(packet.payload);
    if (command_ == nullptr || request.connection_number != command_->connection_number ||
        event_ != nullptr) {
      log::Warn("PTP/IP camera: refusing event connection {} (no matching command connection)",
                request.connection_number);
      connection.Send(ptp::Encode(ptp::InitFail{1}));
      return false;
    }
    log::Debug("PTP/IP camera: InitEventRequest on fd {}", connection.fd());
    connection.role = ConnectionRole::kEvent;
    event_ = &connection;
    return connection.Send(ptp::EncodeInitEventAck());
  }
  log::Warn("PTP/IP camera: {} before the Init handshake", ptp::PacketTypeName(packet.type));
  return false;
}

bool PtpIpCamera::HandleCommand(Connection& /*connection*/, const Packet& packet) {
  switch (packet.type) {
    case PacketType::kOperationRequest: {
      const ptp::OperationRequest request = ptp::DecodeOperationRequest(packet.payload);
      if (ptp::PtpResponder::ExpectsDataFromInitiator(request.code)) {
        pending_ = PendingDataOut{request, {}, 0, false};
        return true;
      }
      return RunOperation(request, {});
    }
    case PacketType::kStartData: {
      const ptp::StartData start = ptp::DecodeStartData(packet.payload);
      if (!pending_ || start.transaction_id != pending_->request.transaction_id) {
        log::Warn("PTP/IP camera: StartData for unexpected transaction {}", start.transaction_id);
        return false;
      }
      pending_->expected = start.total_length;
      pending_->started = true;
      // libgphoto2 sends no EndData for an empty data phase.
      if (start.total_length == 0) {
        PendingDataOut done = std::move(*pending_);
        pending_.reset();
        return RunOperation(done.request, done.data);
      }
      return true;
    }
    case PacketType::kData:
    case PacketType::kEndData: {
      ptp::DataChunk chunk = ptp::DecodeDataChunk(packet.payload);
      if (!pending_ || !pending_->started ||
          chunk.transaction_id != pending_->request.transaction_id) {
        log::Warn("PTP/IP camera: data for unexpected transaction {}", chunk.transaction_id);
        return false;
      }
      pending_->data.insert(pending_->data.end(), chunk.bytes.begin(), chunk.bytes.end());
      if (pending_->data.size() > pending_->expected) {
        log::Warn("PTP/IP camera: {} data bytes, StartData announced {}", pending_->data.size(),
                  pending_->expected);
        return false;
      }
      if (packet.type == PacketType::kEndData) {
        PendingDataOut done = std::move(*pending_);
        pending_.reset();
        return RunOperation(done.request, done.data);
      }
      return true;
    }
    case PacketType::kCancel:
      pending_.reset();
      return true;
    default:
      log::Warn("PTP/IP camera: unexpected {} on the command connection",
                ptp::PacketTypeName(packet.type));
      return false;
  }
}

bool PtpIpCamera::RunOperation(const ptp::OperationRequest& request,
                               const std::vector<uint8_t>& data_in) {
  ptp::PtpResult result;
  {
    std::lock_guard lock(mutex_);
    result = responder_.Handle(request, data_in);
    if (result.code == ptp::kRcOperationNotSupported) ++unsupported_requests_;
  }
  log::Debug("PTP/IP camera: op 0x{:04x} tid {} -> 0x{:04x}", request.code, request.transaction_id,
             result.code);
  if (result.data && !SendData(request.transaction_id, *result.data)) return false;
  ptp::OperationResponse response{result.code, request.transaction_id, result.params};
  if (!command_->Send(ptp::Encode(response))) return false;
  if (result.start_capture) RunCapture(request.transaction_id);
  // libgphoto2 2.5.30's generic capture logs a refused InitiateCapture but then waits for
  // capture events with no deadline; ending the transaction with CaptureComplete (and no
  // ObjectAdded) lets it give up and report the busy camera instead of hanging.
  if (request.code == ptp::kOpInitiateCapture && result.code == ptp::kRcDeviceBusy) {
    SendEvent(ptp::kEventCaptureComplete, request.transaction_id, {});
  }
  return true;
}

bool PtpIpCamera::SendData(uint32_t transaction_id, const std::vector<uint8_t>& data) {
  if (!command_->Send(ptp::Encode(ptp::StartData{transaction_id, data.size()}))) return false;
  size_t offset = 0;
  do {
    const size_t count = std::min(kDataChunkBytes, data.size() - offset);
    const bool last = offset + count == data.size();
    ptp::DataChunk chunk{
        transaction_id,
        std::vector<uint8_t>(data.begin() + static_cast<ptrdiff_t>(offset),
                             data.begin() + static_cast<ptrdiff_t>(offset + count))};
    if (!command_->Send(ptp::Encode(chunk, last))) return false;
    offset += count;
  } while (offset < data.size());
  return true;
}

void PtpIpCamera::RunCapture(uint32_t transaction_id) {
  const double start_s = clock_->NowSeconds();
  EmulatedSettings settings;
  {
    std::lock_guard lock(mutex_);
    settings = responder_.settings();
  }
  std::optional<uint32_t> handle;
  try {
    EmulatedFrame frame = options_.frame_source(settings);
    clock_->SleepUntil(start_s + options_.capture_latency_s);
    std::lock_guard lock(mutex_);
    handle = responder_.store().Add(std::move(frame));
    ++captures_;
  } catch (const std::exception& e) {
    // A camera that fails to write the card completes the capture without an object.
    log::Error("PTP/IP camera: capture failed: {}", e.what());
  }
  // Both events carry the InitiateCapture's transaction id (PTP 1.0 section 10.4.2).
  if (handle) SendEvent(ptp::kEventObjectAdded, transaction_id, {*handle});
  SendEvent(ptp::kEventCaptureComplete, transaction_id, {});
}

void PtpIpCamera::SendEvent(uint16_t code, uint32_t transaction_id, std::vector<uint32_t> params) {
  if (event_ == nullptr) return;
  ptp::EventMessage event{code, transaction_id, std::move(params)};
  if (!event_->Send(ptp::Encode(event))) CloseConnection(event_);
}

void PtpIpCamera::CloseConnection(Connection* connection) {
  if (connection == command_) {
    CloseClient();
    return;
  }
  if (connection == event_) event_ = nullptr;
  std::erase_if(connections_, [&](const auto& c) { return c.get() == connection; });
}

void PtpIpCamera::CloseClient() {
  // The command connection carries the session: without it the event connection is useless.
  Connection* command = command_;
  Connection* event = event_;
  command_ = event_ = nullptr;
  pending_.reset();
  std::erase_if(connections_,
                [&](const auto& c) { return c.get() == command || c.get() == event; });
  std::lock_guard lock(mutex_);
  responder_.EndSession();
}

}  // namespace avc::sim
