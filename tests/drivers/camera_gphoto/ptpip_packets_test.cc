// PTP/IP framing and payload codecs: every packet type survives encode -> decode, a stream is cut
// into packets whatever its chunking, and truncated or corrupt input is a PtpDecodeError naming
// the field, never a crash.

#include "sim/emulators/ptpip/ptpip_packets.h"

#include <gtest/gtest.h>

#include <string>

#include "sim/emulators/ptpip/byte_io.h"
#include "sim/emulators/ptpip/ptp_codes.h"

namespace avc::sim::ptp {
namespace {

// Payload of a whole encoded packet, checking its header on the way.
std::vector<uint8_t> PayloadOf(std::vector<uint8_t> bytes, PacketType expected) {
  std::optional<Packet> packet = TakePacket(bytes);
  EXPECT_TRUE(packet.has_value());
  EXPECT_TRUE(bytes.empty()) << "bytes left after one packet";
  EXPECT_EQ(static_cast<uint32_t>(packet->type), static_cast<uint32_t>(expected));
  return packet->payload;
}

TEST(PtpIpPackets, InitCommandRequestRoundTrip) {
  InitCommandRequest in;
  for (size_t i = 0; i < in.guid.size(); ++i) in.guid[i] = static_cast<uint8_t>(0xA0 + i);
  in.host_name = "cell-pc";
  in.version = kPtpIpVersion;
  const std::vector<uint8_t> bytes = Encode(in);
  // 8 header + 16 guid + (7 + 1) * 2 name + 4 version, as libgphoto2 sends it.
  EXPECT_EQ(bytes.size(), 44u);
  const InitCommandRequest out =
      DecodeInitCommandRequest(PayloadOf(bytes, PacketType::kInitCommandRequest));
  EXPECT_EQ(out.guid, in.guid);
  EXPECT_EQ(out.host_name, "cell-pc");
  EXPECT_EQ(out.version, kPtpIpVersion);
}

TEST(PtpIpPackets, InitAcksAndEventRequestRoundTrip) {
  InitCommandAck ack{7, {}, "AVC camera", kPtpIpVersion};
  ack.guid[15] = 0x42;
  const InitCommandAck ack_out =
      DecodeInitCommandAck(PayloadOf(Encode(ack), PacketType::kInitCommandAck));
  EXPECT_EQ(ack_out.connection_number, 7u);
  EXPECT_EQ(ack_out.guid, ack.guid);
  EXPECT_EQ(ack_out.name, "AVC camera");

  EXPECT_EQ(
      DecodeInitEventRequest(PayloadOf(Encode(InitEventRequest{7}), PacketType::kInitEventRequest))
          .connection_number,
      7u);
  EXPECT_TRUE(PayloadOf(EncodeInitEventAck(), PacketType::kInitEventAck).empty());
  EXPECT_EQ(DecodeInitFail(PayloadOf(Encode(InitFail{3}), PacketType::kInitFail)).reason, 3u);
  EXPECT_TRUE(PayloadOf(EncodePing(), PacketType::kPing).empty());
  EXPECT_TRUE(PayloadOf(EncodePong(), PacketType::kPong).empty());
}

TEST(PtpIpPackets, OperationResponseAndEventRoundTrip) {
  const OperationRequest request{2, 0x1016, 41, {0x500F}};
  const OperationRequest request_out =
      DecodeOperationRequest(PayloadOf(Encode(request), PacketType::kOperationRequest));
  EXPECT_EQ(request_out.data_phase, 2u);
  EXPECT_EQ(request_out.code, 0x1016);
  EXPECT_EQ(request_out.transaction_id, 41u);
  EXPECT_EQ(request_out.params, std::vector<uint32_t>{0x500F});

  const OperationResponse response{0x2019, 42, {1, 2, 3, 4, 5}};
  const OperationResponse response_out =
      DecodeOperationResponse(PayloadOf(Encode(response), PacketType::kOperationResponse));
  EXPECT_EQ(response_out.code, 0x2019);
  EXPECT_EQ(response_out.transaction_id, 42u);
  EXPECT_EQ(response_out.params, response.params);

  const EventMessage event{0x4002, 43, {9}};
  const EventMessage event_out = DecodeEvent(PayloadOf(Encode(event), PacketType::kEvent));
  EXPECT_EQ(event_out.code, 0x4002);
  EXPECT_EQ(event_out.transaction_id, 43u);
  EXPECT_EQ(event_out.params, std::vector<uint32_t>{9});
}

TEST(PtpIpPackets, DataPhaseRoundTrip) {
  const StartData start{5, 0x1'0000'0002ull};
  const StartData start_out = DecodeStartData(PayloadOf(Encode(start), PacketType::kStartData));
  EXPECT_EQ(start_out.transaction_id, 5u);
  EXPECT_EQ(start_out.total_length, 0x1'0000'0002ull);

  const DataChunk chunk{5, {1, 2, 3, 250}};
  EXPECT_EQ(DecodeDataChunk(PayloadOf(Encode(chunk, false), PacketType::kData)).bytes, chunk.bytes);
  const DataChunk end = DecodeDataChunk(PayloadOf(Encode(chunk, true), PacketType::kEndData));
  EXPECT_EQ(end.transaction_id, 5u);
  EXPECT_EQ(end.bytes, chunk.bytes);
}

TEST(PtpIpPackets, StreamIsCutIntoPacketsWhateverTheChunking) {
  std::vector<uint8_t> wire;
  for (uint32_t tid = 1; tid <= 3; ++tid) {
    const std::vector<uint8_t> packet = Encode(OperationResponse{0x2001, tid, {}});
    wire.insert(wire.end(), packet.begin(), packet.end());
  }
  // Feed one byte at a time: nothing comes out early, all three come out in order.
  std::vector<uint8_t> stream;
  std::vector<uint32_t> seen;
  for (uint8_t byte : wire) {
    stream.push_back(byte);
    while (std::optional<Packet> packet = TakePacket(stream)) {
      seen.push_back(DecodeOperationResponse(packet->payload).transaction_id);
    }
  }
  EXPECT_EQ(seen, (std::vector<uint32_t>{1, 2, 3}));
  EXPECT_TRUE(stream.empty());
}

TEST(PtpIpPackets, CorruptLengthIsAnError) {
  std::vector<uint8_t> too_short = {4, 0, 0, 0, 6, 0, 0, 0};
  EXPECT_THROW(TakePacket(too_short), PtpDecodeError);
  std::vector<uint8_t> too_long = {0xFF, 0xFF, 0xFF, 0x7F, 6, 0, 0, 0};
  try {
    TakePacket(too_long);
    FAIL() << "a 2 GB packet was accepted";
  } catch (const PtpDecodeError& e) {
    EXPECT_NE(std::string(e.what()).find("length"), std::string::npos) << e.what();
  }
}

TEST(PtpIpPackets, TruncatedPayloadsNameTheField) {
  const std::vector<uint8_t> request =
      PayloadOf(Encode(InitCommandRequest{{}, "host", 0x10000}), PacketType::kInitCommandRequest);
  // Every proper prefix must fail cleanly.
  for (size_t size = 0; size < request.size(); ++size) {
    EXPECT_THROW(DecodeInitCommandRequest(std::span(request.data(), size)), PtpDecodeError)
        << "prefix of " << size << " bytes";
  }
  try {
    DecodeInitCommandRequest(std::span(request.data(), 10));
    FAIL();
  } catch (const PtpDecodeError& e) {
    EXPECT_NE(std::string(e.what()).find("InitCommandRequest"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("guid"), std::string::npos) << e.what();
  }
  const std::vector<uint8_t> response = {0x01, 0x20, 0x05, 0x00};  // code + half a tid
  EXPECT_THROW(DecodeOperationResponse(response), PtpDecodeError);
  const std::vector<uint8_t> ragged = {0x01, 0x20, 5, 0, 0, 0, 1, 2};  // 2 bytes of a param
  EXPECT_THROW(DecodeOperationResponse(ragged), PtpDecodeError);
  EXPECT_THROW(DecodeStartData(std::vector<uint8_t>(11, 0)), PtpDecodeError);
  EXPECT_THROW(DecodeDataChunk(std::vector<uint8_t>(3, 0)), PtpDecodeError);
}

TEST(PtpIpPackets, TooManyParametersAreRefused) {
  EXPECT_THROW(Encode(OperationRequest{1, 0x1001, 1, {1, 2, 3, 4, 5, 6}}), std::invalid_argument);
  EXPECT_THROW(Encode(EventMessage{0x4002, 1, {1, 2, 3, 4}}), std::invalid_argument);
  ByteWriter w;
  w.U16(0x4002);
  w.U32(1);
  for (uint32_t p = 0; p < 4; ++p) w.U32(p);
  EXPECT_THROW(DecodeEvent(w.bytes()), PtpDecodeError);
}

}  // namespace
}  // namespace avc::sim::ptp
