#include "sim/emulators/ptpip/ptpip_packets.h"

#include <fmt/format.h>

#include <algorithm>

#include "sim/emulators/ptpip/byte_io.h"

namespace avc::sim::ptp {
namespace {

// Parameters are whole uint32s after the fixed part; a ragged tail means a corrupt packet.
std::vector<uint32_t> ReadParams(ByteReader& reader, size_t max_params, const char* what) {
  if (reader.remaining() % 4 != 0) {
    throw PtpDecodeError(fmt::format("{}: {} parameter bytes is not a whole number of uint32", what,
                                     reader.remaining()));
  }
  const size_t count = reader.remaining() / 4;
  if (count > max_params) {
    throw PtpDecodeError(
        fmt::format("{}: {} parameters, at most {} allowed", what, count, max_params));
  }
  std::vector<uint32_t> params(count);
  for (auto& p : params) p = reader.U32("parameter");
  return params;
}

void WriteParams(ByteWriter& writer, const std::vector<uint32_t>& params, size_t max_params,
                 const char* what) {
  if (params.size() > max_params) {
    throw std::invalid_argument(
        fmt::format("{}: {} parameters, at most {} allowed", what, params.size(), max_params));
  }
  for (uint32_t p : params) writer.U32(p);
}

std::vector<uint8_t> Finish(PacketType type, const ByteWriter& writer) {
  return EncodePacket(type, writer.bytes());
}

}  // namespace

const char* PacketTypeName(PacketType type) {
  switch (type) {
    case PacketType::kInitCommandRequest:
      return "InitCommandRequest";
    case PacketType::kInitCommandAck:
      return "InitCommandAck";
    case PacketType::kInitEventRequest:
      return "InitEventRequest";
    case PacketType::kInitEventAck:
      return "InitEventAck";
    case PacketType::kInitFail:
      return "InitFail";
    case PacketType::kOperationRequest:
      return "OperationRequest";
    case PacketType::kOperationResponse:
      return "OperationResponse";
    case PacketType::kEvent:
      return "Event";
    case PacketType::kStartData:
      return "StartData";
    case PacketType::kData:
      return "Data";
    case PacketType::kCancel:
      return "Cancel";
    case PacketType::kEndData:
      return "EndData";
    case PacketType::kPing:
      return "Ping";
    case PacketType::kPong:
      return "Pong";
  }
  return "unknown";
}

std::vector<uint8_t> EncodePacket(PacketType type, std::span<const uint8_t> payload) {
  ByteWriter writer;
  writer.U32(static_cast<uint32_t>(kPacketHeaderBytes + payload.size()));
  writer.U32(static_cast<uint32_t>(type));
  writer.Bytes(payload);
  return writer.Take();
}

std::optional<Packet> TakePacket(std::vector<uint8_t>& stream) {
  if (stream.size() < kPacketHeaderBytes) return std::nullopt;
  ByteReader header(std::span(stream.data(), kPacketHeaderBytes), "PTP/IP packet header");
  const uint32_t length = header.U32("length");
  const uint32_t type = header.U32("type");
  if (length < kPacketHeaderBytes || length > kMaxPacketBytes) {
    throw PtpDecodeError(fmt::format("PTP/IP packet header: length {} outside [{}, {}] (type {})",
                                     length, kPacketHeaderBytes, kMaxPacketBytes, type));
  }
  if (stream.size() < length) return std::nullopt;
  Packet packet{static_cast<PacketType>(type),
                std::vector<uint8_t>(stream.begin() + kPacketHeaderBytes, stream.begin() + length)};
  stream.erase(stream.begin(), stream.begin() + length);
  return packet;
}

std::vector<uint8_t> Encode(const InitCommandRequest& m) {
  ByteWriter w;
  w.Bytes(m.guid);
  w.Utf16Z(m.host_name);
  w.U32(m.version);
  return Finish(PacketType::kInitCommandRequest, w);
}

std::vector<uint8_t> Encode(const InitCommandAck& m) {
  ByteWriter w;
  w.U32(m.connection_number);
  w.Bytes(m.guid);
  w.Utf16Z(m.name);
  w.U32(m.version);
  return Finish(PacketType::kInitCommandAck, w);
}

std::vector<uint8_t> Encode(const InitEventRequest& m) {
  ByteWriter w;
  w.U32(m.connection_number);
  return Finish(PacketType::kInitEventRequest, w);
}

std::vector<uint8_t> EncodeInitEventAck() { return EncodePacket(PacketType::kInitEventAck, {}); }

std::vector<uint8_t> Encode(const InitFail& m) {
  ByteWriter w;
  w.U32(m.reason);
  return Finish(PacketType::kInitFail, w);
}

std::vector<uint8_t> Encode(const OperationRequest& m) {
  ByteWriter w;
  w.U32(m.data_phase);
  w.U16(m.code);
  w.U32(m.transaction_id);
  WriteParams(w, m.params, 5, "PTP/IP OperationRequest");
  return Finish(PacketType::kOperationRequest, w);
}

std::vector<uint8_t> Encode(const OperationResponse& m) {
  ByteWriter w;
  w.U16(m.code);
  w.U32(m.transaction_id);
  WriteParams(w, m.params, 5, "PTP/IP OperationResponse");
  return Finish(PacketType::kOperationResponse, w);
}

std::vector<uint8_t> Encode(const EventMessage& m) {
  ByteWriter w;
  w.U16(m.code);
  w.U32(m.transaction_id);
  WriteParams(w, m.params, 3, "PTP/IP Event");
  return Finish(PacketType::kEvent, w);
}

std::vector<uint8_t> Encode(const StartData& m) {
  ByteWriter w;
  w.U32(m.transaction_id);
  w.U64(m.total_length);
  return Finish(PacketType::kStartData, w);
}

std::vector<uint8_t> Encode(const DataChunk& m, bool last) {
  ByteWriter w;
  w.U32(m.transaction_id);
  w.Bytes(m.bytes);
  return Finish(last ? PacketType::kEndData : PacketType::kData, w);
}

std::vector<uint8_t> EncodePing() { return EncodePacket(PacketType::kPing, {}); }
std::vector<uint8_t> EncodePong() { return EncodePacket(PacketType::kPong, {}); }

InitCommandRequest DecodeInitCommandRequest(std::span<const uint8_t> payload) {
  ByteReader r(payload, "PTP/IP InitCommandRequest");
  InitCommandRequest m;
  const std::vector<uint8_t> guid = r.Bytes(m.guid.size(), "guid");
  std::copy(guid.begin(), guid.end(), m.guid.begin());
  m.host_name = r.Utf16Z("host name");
  m.version = r.U32("version");
  return m;
}

InitCommandAck DecodeInitCommandAck(std::span<const uint8_t> payload) {
  ByteReader r(payload, "PTP/IP InitCommandAck");
  InitCommandAck m;
  m.connection_number = r.U32("connection number");
  const std::vector<uint8_t> guid = r.Bytes(m.guid.size(), "guid");
  std::copy(guid.begin(), guid.end(), m.guid.begin());
  m.name = r.Utf16Z("name");
  m.version = r.U32("version");
  return m;
}

InitEventRequest DecodeInitEventRequest(std::span<const uint8_t> payload) {
  ByteReader r(payload, "PTP/IP InitEventRequest");
  return {r.U32("connection number")};
}

InitFail DecodeInitFail(std::span<const uint8_t> payload) {
  ByteReader r(payload, "PTP/IP InitFail");
  return {r.U32("reason")};
}

OperationRequest DecodeOperationRequest(std::span<const uint8_t> payload) {
  ByteReader r(payload, "PTP/IP OperationRequest");
  OperationRequest m;
  m.data_phase = r.U32("data phase");
  m.code = r.U16("operation code");
  m.transaction_id = r.U32("transaction id");
  m.params = ReadParams(r, 5, "PTP/IP OperationRequest");
  return m;
}

OperationResponse DecodeOperationResponse(std::span<const uint8_t> payload) {
  ByteReader r(payload, "PTP/IP OperationResponse");
  OperationResponse m;
  m.code = r.U16("response code");
  m.transaction_id = r.U32("transaction id");
  m.params = ReadParams(r, 5, "PTP/IP OperationResponse");
  return m;
}

EventMessage DecodeEvent(std::span<const uint8_t> payload) {
  ByteReader r(payload, "PTP/IP Event");
  EventMessage m;
  m.code = r.U16("event code");
  m.transaction_id = r.U32("transaction id");
  m.params = ReadParams(r, 3, "PTP/IP Event");
  return m;
}

StartData DecodeStartData(std::span<const uint8_t> payload) {
  ByteReader r(payload, "PTP/IP StartData");
  StartData m;
  m.transaction_id = r.U32("transaction id");
  m.total_length = r.U64("total length");
  return m;
}

DataChunk DecodeDataChunk(std::span<const uint8_t> payload) {
  ByteReader r(payload, "PTP/IP Data");
  DataChunk m;
  m.transaction_id = r.U32("transaction id");
  m.bytes = r.Rest();
  return m;
}

}  // namespace avc::sim::ptp
