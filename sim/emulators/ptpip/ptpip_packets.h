#pragma once

// PTP/IP framing (CIPA DC-005; libgphoto2 camlibs/ptp2/PTPIP.TXT): every packet is
// uint32 length (header included), uint32 type, payload. Encoders return whole packets;
// decoders take the payload of one packet and throw PtpDecodeError on truncated input.

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace avc::sim::ptp {

enum class PacketType : uint32_t {
  kInitCommandRequest = 1,
  kInitCommandAck = 2,
  kInitEventRequest = 3,
  kInitEventAck = 4,
  kInitFail = 5,
  kOperationRequest = 6,
  kOperationResponse = 7,
  kEvent = 8,
  kStartData = 9,
  kData = 10,
  kCancel = 11,
  kEndData = 12,
  kPing = 13,
  kPong = 14,
};

const char* PacketTypeName(PacketType type);

inline constexpr size_t kPacketHeaderBytes = 8;
// Larger packets are refused as corrupt (image data travels in many Data packets).
inline constexpr size_t kMaxPacketBytes = 16u << 20;

struct Packet {
  PacketType type;
  std::vector<uint8_t> payload;
};

std::vector<uint8_t> EncodePacket(PacketType type, std::span<const uint8_t> payload);

// Removes one whole packet from the front of a stream buffer; nullopt while it is incomplete.
// Throws PtpDecodeError for a length below the header size or above kMaxPacketBytes.
std::optional<Packet> TakePacket(std::vector<uint8_t>& stream);

using Guid = std::array<uint8_t, 16>;

struct InitCommandRequest {
  Guid guid{};
  std::string host_name;
  uint32_t version = 0;  // major << 16 | minor
};

struct InitCommandAck {
  uint32_t connection_number = 0;
  Guid guid{};
  std::string name;
  uint32_t version = 0;
};

struct InitEventRequest {
  uint32_t connection_number = 0;
};

struct InitFail {
  uint32_t reason = 0;
};

// Operation request (command), response and event share code + transaction id + params.
struct OperationRequest {
  uint32_t data_phase = 1;
  uint16_t code = 0;
  uint32_t transaction_id = 0;
  std::vector<uint32_t> params;  // at most 5
};

struct OperationResponse {
  uint16_t code = 0;
  uint32_t transaction_id = 0;
  std::vector<uint32_t> params;  // at most 5
};

struct EventMessage {
  uint16_t code = 0;
  uint32_t transaction_id = 0;
  std::vector<uint32_t> params;  // at most 3
};

struct StartData {
  uint32_t transaction_id = 0;
  uint64_t total_length = 0;
};

// Data and EndData packets carry the same payload.
struct DataChunk {
  uint32_t transaction_id = 0;
  std::vector<uint8_t> bytes;
};

std::vector<uint8_t> Encode(const InitCommandRequest& m);
std::vector<uint8_t> Encode(const InitCommandAck& m);
std::vector<uint8_t> Encode(const InitEventRequest& m);
std::vector<uint8_t> EncodeInitEventAck();
std::vector<uint8_t> Encode(const InitFail& m);
std::vector<uint8_t> Encode(const OperationRequest& m);
std::vector<uint8_t> Encode(const OperationResponse& m);
std::vector<uint8_t> Encode(const EventMessage& m);
std::vector<uint8_t> Encode(const StartData& m);
// last = true makes an EndData packet, else a Data packet.
std::vector<uint8_t> Encode(const DataChunk& m, bool last);
std::vector<uint8_t> EncodePing();
std::vector<uint8_t> EncodePong();

InitCommandRequest DecodeInitCommandRequest(std::span<const uint8_t> payload);
InitCommandAck DecodeInitCommandAck(std::span<const uint8_t> payload);
InitEventRequest DecodeInitEventRequest(std::span<const uint8_t> payload);
InitFail DecodeInitFail(std::span<const uint8_t> payload);
OperationRequest DecodeOperationRequest(std::span<const uint8_t> payload);
OperationResponse DecodeOperationResponse(std::span<const uint8_t> payload);
EventMessage DecodeEvent(std::span<const uint8_t> payload);
StartData DecodeStartData(std::span<const uint8_t> payload);
DataChunk DecodeDataChunk(std::span<const uint8_t> payload);

}  // namespace avc::sim::ptp
