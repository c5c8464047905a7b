#include "drivers/robot/primary_protocol.h"

#include <fmt/format.h>

#include <stdexcept>

#include "drivers/robot/big_endian.h"

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
  BigEndianWriter framed;
  framed.U32(static_cast<uint32_t>(kHeaderSize + body.bytes().size()));
  framed.U8(kRobotMessageType);
  auto bytes = std::move(framed.bytes());
  bytes.insert(bytes.end(), body.bytes().begin(), body.bytes().end());
  return bytes;
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

namespace {

std::vector<uint8_t> Frame(uint8_t type, const std::vector<uint8_t>& body) {
  BigEndianWriter framed;
  framed.U32(static_cast<uint32_t>(kHeaderSize + body.size()));
  framed.U8(type);
  auto bytes = std::move(framed.bytes());
  bytes.insert(bytes.end(), body.begin(), body.end());
  return bytes;
}

}  // namespace

std::vector<uint8_t> EncodeVersionMessage(const VersionMessage& version, uint64_t timestamp) {
  BigEndianWriter body;
  body.U64(timestamp);
  body.U8(static_cast<uint8_t>(-1));  // source: controller
  body.U8(kVersionMessage);
  body.U8(static_cast<uint8_t>(version.project_name.size()));
  body.Bytes(version.project_name);
  body.U8(version.major);
  body.U8(version.minor);
  body.I32(version.bugfix);
  body.I32(version.build);
  body.Bytes(version.build_date);
  return Frame(kRobotMessageType, body.bytes());
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

std::vector<uint8_t> EncodeKinematicsState(const KinematicsInfo& info) {
  BigEndianWriter sub;
  for (uint32_t c : info.checksum) sub.U32(c);
  for (const auto* values : {&info.theta, &info.a, &info.d, &info.alpha}) {
    for (double v : *values) sub.F64(v);
  }
  sub.U32(info.calibration_status);
  // Sub-packages are framed like packages: int32 size (incl. header) + uint8 type.
  return Frame(kRobotStateType, Frame(kKinematicsInfoType, sub.bytes()));
}

std::optional<KinematicsInfo> FindKinematicsInfo(const std::vector<uint8_t>& body) {
  size_t offset = 0;
  while (offset + kHeaderSize <= body.size()) {
    BigEndianReader header(body.data() + offset, body.size() - offset, "ROBOT_STATE sub-package");
    const uint32_t size = header.U32();
    const uint8_t type = header.U8();
    if (size < kHeaderSize || size > body.size() - offset) {
      throw std::runtime_error(
          fmt::format("ROBOT_STATE sub-package at offset {} announces {} bytes", offset, size));
    }
    if (type == kKinematicsInfoType) {
      BigEndianReader reader(body.data() + offset + kHeaderSize, size - kHeaderSize,
                             "KINEMATICS_INFO");
      KinematicsInfo info;
      for (auto& c : info.checksum) c = reader.U32();
      for (auto* values : {&info.theta, &info.a, &info.d, &info.alpha}) {
        for (double& v : *values) v = reader.F64();
      }
      info.calibration_status = reader.U32();
      return info;
    }
    offset += size;
  }
  return std::nullopt;
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
