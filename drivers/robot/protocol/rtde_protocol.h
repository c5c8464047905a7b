#pragma once

// The RTDE wire protocol (port 30004), both directions: framing (uint16 size including the
// 3-byte header, uint8 type, payload; big-endian) and the payload of every packet a CB3
// controller speaks at protocol versions 1 and 2. Pure encode/decode, no sockets; the client and
// the emulator share it. Layouts follow UniversalRobots/RTDE_Python_Client_Library rtde.py and
// serialize.py.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace avc::robot::rtde {

enum class PacketType : uint8_t {
  kRequestProtocolVersion = 86,  // 'V'
  kGetUrcontrolVersion = 118,    // 'v'
  kTextMessage = 77,             // 'M'
  kDataPackage = 85,             // 'U'
  kSetupOutputs = 79,            // 'O'
  kSetupInputs = 73,             // 'I'
  kStart = 83,                   // 'S'
  kPause = 80,                   // 'P'
};

// "V(86)" style name for messages; unknown types print their number.
std::string PacketTypeName(uint8_t type);

inline constexpr size_t kHeaderSize = 3;
inline constexpr size_t kMaxPacketSize = 65535;
// UR manual: the comma-separated variable list of one recipe is at most 2048 bytes.
inline constexpr size_t kMaxNameListBytes = 2048;

struct Packet {
  uint8_t type = 0;
  std::vector<uint8_t> payload;
};

// Header + payload. Throws std::invalid_argument when the packet would exceed 65535 bytes.
std::vector<uint8_t> EncodePacket(PacketType type, const std::vector<uint8_t>& payload);

// Splits a byte stream into packets. Throws std::runtime_error on a header whose size is below
// the header's own 3 bytes (the stream cannot be resynchronised after that).
class PacketFramer {
 public:
  void Append(const uint8_t* data, size_t size);
  std::optional<Packet> Next();
  size_t buffered() const { return buffer_.size() - start_; }

 private:
  std::vector<uint8_t> buffer_;
  size_t start_ = 0;
};

// --- Wire value types -------------------------------------------------------------------------

enum class ValueType {
  kBool,
  kUint8,
  kUint32,
  kUint64,
  kInt32,
  kDouble,
  kVector3d,
  kVector6d,
  kVector6Int32,
  kVector6Uint32,
};

// "DOUBLE", "VECTOR6D", ... as the controller writes them.
std::string_view ValueTypeName(ValueType type);
// nullopt for "NOT_FOUND", "IN_USE" and anything unknown (STRING is not used in data packages).
std::optional<ValueType> ParseValueType(std::string_view name);

using Value =
    std::variant<bool, uint8_t, uint32_t, uint64_t, int32_t, double, std::array<double, 3>,
                 std::array<double, 6>, std::array<int32_t, 6>, std::array<uint32_t, 6>>;
// The variant alternative index of each ValueType matches its enum order.
ValueType TypeOf(const Value& value);

// --- Payloads ---------------------------------------------------------------------------------

// 'V' request: the protocol version the client asks for.
std::vector<uint8_t> EncodeProtocolVersionRequest(uint16_t version);
uint16_t DecodeProtocolVersionRequest(const std::vector<uint8_t>& payload);

// Replies to 'V', 'S' and 'P': one byte, non-zero when accepted.
std::vector<uint8_t> EncodeAccepted(bool accepted);
bool DecodeAccepted(const std::vector<uint8_t>& payload, std::string_view what);

struct ControllerVersion {
  uint32_t major = 0, minor = 0, bugfix = 0, build = 0;
  std::string ToString() const;
  bool operator==(const ControllerVersion&) const = default;
};
std::vector<uint8_t> EncodeControllerVersion(const ControllerVersion& version);
ControllerVersion DecodeControllerVersion(const std::vector<uint8_t>& payload);

// 'O' request: v2 sends the frequency (double) before the names; v1 only the names.
struct SetupOutputsRequest {
  double frequency = 125.0;
  std::vector<std::string> names;
};
std::vector<uint8_t> EncodeSetupOutputsRequest(const SetupOutputsRequest& request,
                                               int protocol_version);
SetupOutputsRequest DecodeSetupOutputsRequest(const std::vector<uint8_t>& payload,
                                              int protocol_version);

// 'I' request: the names only.
std::vector<uint8_t> EncodeSetupInputsRequest(const std::vector<std::string>& names);
std::vector<std::string> DecodeSetupInputsRequest(const std::vector<uint8_t>& payload);

// Reply to 'O' and 'I' (`request`): recipe id + comma-separated type names, "NOT_FOUND" (unknown
// variable) or "IN_USE" (an input another client owns) in place of a type. A protocol v1 'O'
// reply has no recipe id (recipe_id is 0 and not written); 'I' replies carry one at every version
// (UR client library ControlPackageSetupOutputs/Inputs::parseWith). Any other `request` throws
// std::invalid_argument.
struct RecipeReply {
  uint8_t recipe_id = 0;
  std::vector<std::string> types;
  bool operator==(const RecipeReply&) const = default;
};
std::vector<uint8_t> EncodeRecipeReply(const RecipeReply& reply, PacketType request,
                                       int protocol_version);
RecipeReply DecodeRecipeReply(const std::vector<uint8_t>& payload, PacketType request,
                              int protocol_version);

// 'M': v2 is len+message, len+source, level; v1 is level + message.
enum class MessageLevel : uint8_t { kException = 0, kError = 1, kWarning = 2, kInfo = 3 };
struct TextMessage {
  std::string message;
  std::string source;
  MessageLevel level = MessageLevel::kInfo;
  bool operator==(const TextMessage&) const = default;
};
std::vector<uint8_t> EncodeTextMessage(const TextMessage& message, int protocol_version);
TextMessage DecodeTextMessage(const std::vector<uint8_t>& payload, int protocol_version);

// 'U': v2 starts with the recipe id, v1 does not; then the values in recipe order.
struct DataPackage {
  uint8_t recipe_id = 0;
  std::vector<Value> values;
};
// Throws std::invalid_argument when the values do not match `types` in number or type.
std::vector<uint8_t> EncodeDataPackage(const DataPackage& package,
                                       const std::vector<ValueType>& types, int protocol_version);
// Throws std::runtime_error when the payload is shorter or longer than `types` needs.
DataPackage DecodeDataPackage(const std::vector<uint8_t>& payload,
                              const std::vector<ValueType>& types, int protocol_version);

// "a,b,c" <-> {"a","b","c"}; an empty string gives an empty list.
std::string JoinNames(const std::vector<std::string>& names);
std::vector<std::string> SplitNames(std::string_view text);

}  // namespace avc::robot::rtde
