#include "drivers/robot/protocol/primary_protocol.h"

#include <fmt/format.h>

#include <stdexcept>

#include "drivers/robot/protocol/big_endian.h"

namespace avc::robot::primary {
namespace {
// Far above any real package; a larger size means the stream lost sync.
constexpr uint32_t kMaxPackageSize = 1u << 20;
}  // namespace

std::vector<uint8_t> EncodeRobotMessage(const RobotMessage& message) {
  BigEndianWriter body;
  body.U64(message.timestamp);
  body.U8(static_cast<uint8_t>(message.source));
  body.U8(message.message_type);
  if (message.message_type == kRuntimeException) {
    body.I32(message.line);
    body.I32(message.column);
  }
  body.Bytes(message.text);
  return FramePackage(kRobotMessageType, body.bytes());
}

std::optional<RobotMessage> DecodeRobotMessage(const std::vector<uint8_t>& body) {
  BigEndianReader reader(body.data(), body.size(), "secondary ROBOT_MESSAGE");
  RobotMessage message;
  message.timestamp = reader.U64();
  message.source = static_cast<int8_t>(reader.U8());
  message.message_type = reader.U8();
  if (message.message_type == kRuntimeException) {
    message.line = reader.I32();
    message.column = reader.I32();
  } else if (message.message_type != kTextMessage) {
    return std::nullopt;
  }
  message.text = reader.Rest();
  return message;
}

std::vector<uint8_t> FramePackage(uint8_t type, const std::vector<uint8_t>& body) {
  BigEndianWriter framed;
  framed.U32(static_cast<uint32_t>(kHeaderSize + body.size()));
  framed.U8(type);
  auto bytes = std::move(framed.bytes());
  bytes.insert(bytes.end(), body.begin(), body.end());
  return bytes;
}

std::vector<uint8_t> EncodeVersionMessage(const VersionMessage& version, uint64_t timestamp) {
  BigEndianWriter body;
  body.U64(timestamp);
  // Source -2, as a real controller's VERSION carries (UR client library test_primary_parser).
  body.U8(static_cast<uint8_t>(-2));
  body.U8(kVersionMessage);
  body.U8(static_cast<uint8_t>(version.project_name.size()));
  body.Bytes(version.project_name);
  body.U8(version.major);
  body.U8(version.minor);
  body.I32(version.bugfix);
  body.I32(version.build);
  body.Bytes(version.build_date);
  return FramePackage(kRobotMessageType, body.bytes());
}

std::optional<VersionMessage> DecodeVersionMessage(const std::vector<uint8_t>& body) {
  BigEndianReader reader(body.data(), body.size(), "secondary VERSION message");
  reader.U64();
  reader.U8();
  if (reader.U8() != kVersionMessage) return std::nullopt;
  VersionMessage version;
  version.project_name = reader.Bytes(reader.U8());
  version.major = reader.U8();
  version.minor = reader.U8();
  version.bugfix = reader.I32();
  version.build = reader.I32();
  version.build_date = reader.Rest();
  return version;
}

void PackageFramer::Append(const uint8_t* data, size_t size) {
  buffer_.insert(buffer_.end(), data, data + size);
}

std::optional<Package> PackageFramer::Next() {
  if (buffer_.size() < kHeaderSize) return std::nullopt;
  BigEndianReader reader(buffer_.data(), buffer_.size(), "secondary package header");
  const uint32_t size = reader.U32();
  if (size < kHeaderSize || size > kMaxPackageSize) {
    throw std::runtime_error(
        fmt::format("secondary stream corrupt: package header announces {} bytes", size));
  }
  if (buffer_.size() < size) return std::nullopt;
  Package package;
  package.type = reader.U8();
  package.body.assign(buffer_.begin() + kHeaderSize, buffer_.begin() + size);
  buffer_.erase(buffer_.begin(), buffer_.begin() + size);
  return package;
}

}  // namespace avc::robot::primary
