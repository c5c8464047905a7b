// The PTP/IP camera emulator through raw sockets, without libgphoto2: the Init handshake on both
// connections, Ping/Pong, a data phase in each direction, OperationNotSupported for opcodes it
// does not implement, events after InitiateCapture, and a corrupt packet closing only that client.

#include "sim/emulators/ptpip/ptpip_camera.h"

#include <arpa/inet.h>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <memory>
#include <stdexcept>

#include "sim/emulators/ptpip/byte_io.h"
#include "sim/emulators/ptpip/ptp_codes.h"
#include "sim/emulators/ptpip/ptp_datasets.h"

namespace avc::sim {
namespace {

using namespace ptp;  // NOLINT: test brevity

// A blocking TCP client that speaks whole PTP/IP packets, with a 2 s receive deadline.
class RawClient {
 public:
  explicit RawClient(int port) : fd_(socket(AF_INET, SOCK_STREAM, 0)) {
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(static_cast<uint16_t>(port));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (connect(fd_, reinterpret_cast<sockaddr*>(&address), sizeof(address)) != 0) {
      throw std::runtime_error("connect failed");
    }
  }
  ~RawClient() { close(fd_); }

  void Send(const std::vector<uint8_t>& bytes) {
    ASSERT_EQ(send(fd_, bytes.data(), bytes.size(), MSG_NOSIGNAL),
              static_cast<ssize_t>(bytes.size()));
  }

  // Next packet, or nullopt when the peer closed or nothing came within 2 s.
  std::optional<Packet> Receive() {
    while (true) {
      if (std::optional<Packet> packet = TakePacket(buffer_)) return packet;
      pollfd p{fd_, POLLIN, 0};
      if (poll(&p, 1, 2000) != 1) return std::nullopt;
      uint8_t chunk[65536];
      const ssize_t n = recv(fd_, chunk, sizeof(chunk), 0);
      if (n <= 0) return std::nullopt;
      buffer_.insert(buffer_.end(), chunk, chunk + n);
    }
  }

 private:
  int fd_;
  std::vector<uint8_t> buffer_;
};

struct Session {
  explicit Session(const PtpIpCamera& camera) : command(camera.port()), event(camera.port()) {
    InitCommandRequest init;
    init.guid[0] = 0x11;
    init.host_name = "raw-test";
    init.version = kPtpIpVersion;
    command.Send(Encode(init));
    const std::optional<Packet> ack = command.Receive();
    EXPECT_TRUE(ack && ack->type == PacketType::kInitCommandAck);
    connection_number = DecodeInitCommandAck(ack->payload).connection_number;
    event.Send(Encode(InitEventRequest{connection_number}));
    const std::optional<Packet> event_ack = event.Receive();
    EXPECT_TRUE(event_ack && event_ack->type == PacketType::kInitEventAck);
  }

  // Runs one operation; returns the data phase (if any) and the response.
  std::pair<std::vector<uint8_t>, OperationResponse> Run(
      uint16_t code, std::vector<uint32_t> params, const std::vector<uint8_t>* out = nullptr) {
    const uint32_t tid = next_tid++;
    command.Send(Encode(
        OperationRequest{out ? kDataPhaseOut : kDataPhaseNoneOrIn, code, tid, std::move(params)}));
    if (out != nullptr) {
      command.Send(Encode(StartData{tid, out->size()}));
      command.Send(Encode(DataChunk{tid, *out}, true));
    }
    std::vector<uint8_t> data;
    while (true) {
      std::optional<Packet> packet = command.Receive();
      if (!packet) throw std::runtime_error("no response");
      if (packet->type == PacketType::kOperationResponse) {
        return {data, DecodeOperationResponse(packet->payload)};
      }
      if (packet->type == PacketType::kData || packet->type == PacketType::kEndData) {
        const DataChunk chunk = DecodeDataChunk(packet->payload);
        EXPECT_EQ(chunk.transaction_id, tid);
        data.insert(data.end(), chunk.bytes.begin(), chunk.bytes.end());
      }
    }
  }

  RawClient command;
  RawClient event;
  uint32_t connection_number = 0;
  uint32_t next_tid = 1;
};

PtpIpCameraOptions Options() {
  PtpIpCameraOptions options;
  options.frame_source = [](const EmulatedSettings& s) {
    EmulatedFrame frame;
    frame.data.assign(200'000, static_cast<uint8_t>(s.iso / 100));  // several Data packets
    frame.file_name = "IMG_0001.JPG";
    return frame;
  };
  return options;
}

TEST(PtpIpCamera, HandshakeRemembersTheClient) {
  PtpIpCamera camera(Options());
  EXPECT_GT(camera.port(), 0);
  EXPECT_EQ(camera.libgphoto2_port(),
            fmt::format("ptpip:127.0.0.1:{}:{}", camera.port(), camera.port()));
  Session session(camera);
  const std::optional<PtpIpClient> client = camera.client();
  ASSERT_TRUE(client.has_value());
  EXPECT_EQ(client->host_name, "raw-test");
  EXPECT_EQ(client->guid[0], 0x11);
  // Ping works on either connection.
  session.event.Send(EncodePing());
  std::optional<Packet> pong = session.event.Receive();
  ASSERT_TRUE(pong.has_value());
  EXPECT_EQ(pong->type, PacketType::kPong);
}

TEST(PtpIpCamera, EventConnectionMustMatchTheCommandConnection) {
  PtpIpCamera camera(Options());
  RawClient stray(camera.port());
  stray.Send(Encode(InitEventRequest{77}));
  const std::optional<Packet> reply = stray.Receive();
  ASSERT_TRUE(reply.has_value());
  EXPECT_EQ(reply->type, PacketType::kInitFail);
}

TEST(PtpIpCamera, OperationsOverTheWire) {
  PtpIpCamera camera(Options());
  Session session(camera);
  EXPECT_EQ(session.Run(kOpOpenSession, {1}).second.code, kRcOk);
  const auto [info_bytes, info_response] = session.Run(kOpGetDeviceInfo, {});
  EXPECT_EQ(info_response.code, kRcOk);
  EXPECT_EQ(DecodeDeviceInfo(info_bytes).model, "AVC PTP/IP camera emulator");

  // Unknown opcodes are answered, and counted, so a test notices what a client tried.
  EXPECT_EQ(session.Run(0x9116, {}).second.code, kRcOperationNotSupported);
  EXPECT_EQ(camera.unsupported_requests(), 1);

  // Data from the initiator: SetDevicePropValue.
  const std::vector<uint8_t> iso = EncodePropValue(kTypeUint16, 1600);
  EXPECT_EQ(session.Run(kOpSetDevicePropValue, {kPropExposureIndex}, &iso).second.code, kRcOk);
  EXPECT_EQ(camera.settings().iso, 1600u);

  // Capture: response first, then ObjectAdded and CaptureComplete on the event connection.
  const auto capture = session.Run(kOpInitiateCapture, {0, 0}).second;
  EXPECT_EQ(capture.code, kRcOk);
  std::optional<Packet> added = session.event.Receive();
  ASSERT_TRUE(added && added->type == PacketType::kEvent);
  const EventMessage added_event = DecodeEvent(added->payload);
  EXPECT_EQ(added_event.code, kEventObjectAdded);
  EXPECT_EQ(added_event.transaction_id, capture.transaction_id);
  std::optional<Packet> complete = session.event.Receive();
  ASSERT_TRUE(complete && complete->type == PacketType::kEvent);
  EXPECT_EQ(DecodeEvent(complete->payload).code, kEventCaptureComplete);
  EXPECT_EQ(camera.captures(), 1);
  EXPECT_EQ(camera.objects_stored(), 1);

  // Download in several Data packets, then delete.
  const uint32_t handle = added_event.params.at(0);
  const auto [image, image_response] = session.Run(kOpGetObject, {handle});
  EXPECT_EQ(image_response.code, kRcOk);
  ASSERT_EQ(image.size(), 200'000u);
  EXPECT_EQ(image[12345], 16);  // iso 1600 / 100
  EXPECT_EQ(session.Run(kOpDeleteObject, {handle, 0}).second.code, kRcOk);
  EXPECT_EQ(camera.objects_stored(), 0);
}

TEST(PtpIpCamera, BusyCaptureEndsWithoutAnObject) {
  PtpIpCamera camera(Options());
  Session session(camera);
  session.Run(kOpOpenSession, {1});
  camera.InjectBusy(1);
  const OperationResponse busy = session.Run(kOpInitiateCapture, {0, 0}).second;
  EXPECT_EQ(busy.code, kRcDeviceBusy);
  std::optional<Packet> event = session.event.Receive();
  ASSERT_TRUE(event.has_value());
  EXPECT_EQ(DecodeEvent(event->payload).code, kEventCaptureComplete);
  EXPECT_EQ(camera.captures(), 0);
  EXPECT_EQ(session.Run(kOpInitiateCapture, {0, 0}).second.code, kRcOk);
}

TEST(PtpIpCamera, CorruptPacketClosesOnlyThatClient) {
  PtpIpCamera camera(Options());
  {
    Session session(camera);
    session.command.Send({3, 0, 0, 0, 6, 0, 0, 0});  // length 3 < header
    EXPECT_FALSE(session.command.Receive().has_value()) << "connection should be closed";
  }
  // The listener survives; a new client gets a session.
  Session again(camera);
  EXPECT_EQ(again.Run(kOpOpenSession, {1}).second.code, kRcOk);
  EXPECT_EQ(camera.sessions_opened(), 1);
}

TEST(PtpIpCamera, DropConnectionsKeepsListening) {
  PtpIpCamera camera(Options());
  auto session = std::make_unique<Session>(camera);
  session->Run(kOpOpenSession, {1});
  camera.DropConnections();
  EXPECT_FALSE(session->command.Receive().has_value());
  EXPECT_FALSE(session->event.Receive().has_value());
  session = std::make_unique<Session>(camera);
  EXPECT_EQ(session->Run(kOpOpenSession, {1}).second.code, kRcOk);
  EXPECT_EQ(camera.sessions_opened(), 2);
  camera.Stop();
  camera.Stop();  // idempotent
}

TEST(PtpIpCamera, RefusesBadOptions) {
  PtpIpCameraOptions no_source;
  EXPECT_THROW(PtpIpCamera{no_source}, std::invalid_argument);
  PtpIpCameraOptions negative = Options();
  negative.capture_latency_s = -1;
  EXPECT_THROW(PtpIpCamera{negative}, std::invalid_argument);
  PtpIpCameraOptions bad_port = Options();
  bad_port.port = 70000;
  EXPECT_THROW(PtpIpCamera{bad_port}, std::invalid_argument);
}

}  // namespace
}  // namespace avc::sim
