#pragma once

// The subset of the primary/secondary interface (30001/30002) the driver reads back after sending
// a script: message framing (int32 size incl. header, uint8 type), ROBOT_MESSAGE text,
// runtime-exception and VERSION messages (Universal_Robots_Client_Library
// primary/robot_message/*). The ROBOT_STATE stream is in primary_robot_state.h; other packages
// are skipped by size.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace avc::robot::primary {

inline constexpr uint8_t kRobotMessageType = 20;
inline constexpr uint8_t kTextMessage = 0;
inline constexpr uint8_t kRuntimeException = 10;
inline constexpr size_t kHeaderSize = 5;

struct RobotMessage {
  uint64_t timestamp = 0;
  int8_t source = 0;
  uint8_t message_type = kTextMessage;
  int32_t line = 0;    // runtime exceptions only
  int32_t column = 0;  // runtime exceptions only
  std::string text;
  bool operator==(const RobotMessage&) const = default;
};

// Framed ROBOT_MESSAGE package (text or runtime exception).
std::vector<uint8_t> EncodeRobotMessage(const RobotMessage& message);
// Decodes a ROBOT_MESSAGE package body (the bytes after the 5-byte header); nullopt for message
// types other than text and runtime exception.
std::optional<RobotMessage> DecodeRobotMessage(const std::vector<uint8_t>& body);

// ROBOT_MESSAGE type 3, sent once on connect: which controller software this is.
inline constexpr uint8_t kVersionMessage = 3;
struct VersionMessage {
  std::string project_name;  // "URControl"
  uint8_t major = 0;
  uint8_t minor = 0;
  int32_t bugfix = 0;
  int32_t build = 0;
  std::string build_date;
  bool operator==(const VersionMessage&) const = default;
};
std::vector<uint8_t> EncodeVersionMessage(const VersionMessage& version, uint64_t timestamp);
// From a ROBOT_MESSAGE body; nullopt when it is another message type.
std::optional<VersionMessage> DecodeVersionMessage(const std::vector<uint8_t>& body);

// Frames a body as a package (or a ROBOT_STATE sub-package: same header): int32 size including
// the 5-byte header, uint8 type.
std::vector<uint8_t> FramePackage(uint8_t type, const std::vector<uint8_t>& body);

struct Package {
  uint8_t type = 0;
  std::vector<uint8_t> body;
};

// Splits the 30002 byte stream into packages; throws std::runtime_error on an impossible size.
class PackageFramer {
 public:
  void Append(const uint8_t* data, size_t size);
  std::optional<Package> Next();

 private:
  std::vector<uint8_t> buffer_;
};

}  // namespace avc::robot::primary
