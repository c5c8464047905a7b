#include "drivers/robot/protocol/rtde_protocol.h"

#include <fmt/format.h>

#include <stdexcept>

#include "drivers/robot/protocol/big_endian.h"

namespace avc::robot::rtde {
namespace {

constexpr std::array<std::string_view, 10> kTypeNames = {
    "BOOL",   "UINT8",    "UINT32",   "UINT64",       "INT32",
    "DOUBLE", "VECTOR3D", "VECTOR6D", "VECTOR6INT32", "VECTOR6UINT32"};

BigEndianReader ReaderFor(const std::vector<uint8_t>& payload, std::string_view what) {
  return BigEndianReader(payload.data(), payload.size(), std::string(what));
}

void ExpectConsumed(const BigEndianReader& reader, std::string_view what) {
  if (reader.Remaining() != 0) {
    throw std::runtime_error(
        fmt::format("{}: {} unexpected trailing byte(s)", what, reader.Remaining()));
  }
}

void CheckNameList(const std::string& joined, std::string_view what) {
  if (joined.size() > kMaxNameListBytes) {
    throw std::invalid_argument(fmt::format("{}: variable list is {} bytes, the limit is {}", what,
                                            joined.size(), kMaxNameListBytes));
  }
}

// v1 'O' replies are types only (RTDE guide, SETUP_OUTPUTS protocol v. 1 Return); 'I' replies
// start with the recipe id at every version.
bool RecipeReplyHasId(PacketType request, int protocol_version) {
  if (request == PacketType::kSetupInputs) return true;
  if (request == PacketType::kSetupOutputs) return protocol_version >= 2;
  throw std::invalid_argument(fmt::format("RTDE recipe reply: {} is not a setup request",
                                          PacketTypeName(static_cast<uint8_t>(request))));
}

std::vector<uint8_t> Take(BigEndianWriter& writer) { return std::move(writer.bytes()); }

template <typename T, size_t N, typename Read>
std::array<T, N> ReadArray(Read read) {
  std::array<T, N> out{};
  for (auto& entry : out) entry = read();
  return out;
}

}  // namespace

std::string PacketTypeName(uint8_t type) {
  if (type >= 32 && type < 127) return fmt::format("'{}'({})", static_cast<char>(type), type);
  return fmt::format("type {}", type);
}

std::vector<uint8_t> EncodePacket(PacketType type, const std::vector<uint8_t>& payload) {
  const size_t size = kHeaderSize + payload.size();
  if (size > kMaxPacketSize) {
    throw std::invalid_argument(fmt::format("RTDE packet {} would be {} bytes, the limit is {}",
                                            PacketTypeName(static_cast<uint8_t>(type)), size,
                                            kMaxPacketSize));
  }
  BigEndianWriter writer;
  writer.U16(static_cast<uint16_t>(size));
  writer.U8(static_cast<uint8_t>(type));
  auto bytes = Take(writer);
  bytes.insert(bytes.end(), payload.begin(), payload.end());
  return bytes;
}

void PacketFramer::Append(const uint8_t* data, size_t size) {
  if (start_ > 0 && start_ == buffer_.size()) {
    buffer_.clear();
    start_ = 0;
  }
  buffer_.insert(buffer_.end(), data, data + size);
}

std::optional<Packet> PacketFramer::Next() {
  if (buffered() < kHeaderSize) return std::nullopt;
  const size_t size = (static_cast<size_t>(buffer_[start_]) << 8) | buffer_[start_ + 1];
  if (size < kHeaderSize) {
    throw std::runtime_error(fmt::format(
        "RTDE stream corrupt: packet header announces {} bytes, less than the 3-byte header",
        size));
  }
  if (buffered() < size) return std::nullopt;
  Packet packet;
  packet.type = buffer_[start_ + 2];
  packet.payload.assign(buffer_.begin() + static_cast<ptrdiff_t>(start_ + kHeaderSize),
                        buffer_.begin() + static_cast<ptrdiff_t>(start_ + size));
  start_ += size;
  if (start_ > 65536) {  // compact now and then so the buffer does not grow without bound
    buffer_.erase(buffer_.begin(), buffer_.begin() + static_cast<ptrdiff_t>(start_));
    start_ = 0;
  }
  return packet;
}

std::string_view ValueTypeName(ValueType type) { return kTypeNames[static_cast<size_t>(type)]; }

std::optional<ValueType> ParseValueType(std::string_view name) {
  for (size_t i = 0; i < kTypeNames.size(); ++i) {
    if (kTypeNames[i] == name) return static_cast<ValueType>(i);
  }
  return std::nullopt;
}

ValueType TypeOf(const Value& value) { return static_cast<ValueType>(value.index()); }

std::vector<uint8_t> EncodeProtocolVersionRequest(uint16_t version) {
  BigEndianWriter writer;
  writer.U16(version);
  return Take(writer);
}

uint16_t DecodeProtocolVersionRequest(const std::vector<uint8_t>& payload) {
  auto reader = ReaderFor(payload, "RTDE protocol version request");
  const uint16_t version = reader.U16();
  ExpectConsumed(reader, "RTDE protocol version request");
  return version;
}

std::vector<uint8_t> EncodeAccepted(bool accepted) { return {static_cast<uint8_t>(accepted)}; }

bool DecodeAccepted(const std::vector<uint8_t>& payload, std::string_view what) {
  auto reader = ReaderFor(payload, what);
  const bool accepted = reader.U8() != 0;
  ExpectConsumed(reader, what);
  return accepted;
}

std::string ControllerVersion::ToString() const {
  return fmt::format("{}.{}.{}.{}", major, minor, bugfix, build);
}

std::vector<uint8_t> EncodeControllerVersion(const ControllerVersion& version) {
  BigEndianWriter writer;
  writer.U32(version.major);
  writer.U32(version.minor);
  writer.U32(version.bugfix);
  writer.U32(version.build);
  return Take(writer);
}

ControllerVersion DecodeControllerVersion(const std::vector<uint8_t>& payload) {
  auto reader = ReaderFor(payload, "RTDE controller version reply");
  ControllerVersion version;
  version.major = reader.U32();
  version.minor = reader.U32();
  version.bugfix = reader.U32();
  version.build = reader.U32();
  ExpectConsumed(reader, "RTDE controller version reply");
  return version;
}

std::vector<uint8_t> EncodeSetupOutputsRequest(const SetupOutputsRequest& request,
                                               int protocol_version) {
  const std::string joined = JoinNames(request.names);
  CheckNameList(joined, "RTDE output recipe");
  BigEndianWriter writer;
  if (protocol_version >= 2) writer.F64(request.frequency);
  writer.Bytes(joined);
  return Take(writer);
}

SetupOutputsRequest DecodeSetupOutputsRequest(const std::vector<uint8_t>& payload,
                                              int protocol_version) {
  auto reader = ReaderFor(payload, "RTDE output setup request");
  SetupOutputsRequest request;
  request.frequency = protocol_version >= 2 ? reader.F64() : 125.0;
  request.names = SplitNames(reader.Rest());
  return request;
}

std::vector<uint8_t> EncodeSetupInputsRequest(const std::vector<std::string>& names) {
  const std::string joined = JoinNames(names);
  CheckNameList(joined, "RTDE input recipe");
  BigEndianWriter writer;
  writer.Bytes(joined);
  return Take(writer);
}

std::vector<std::string> DecodeSetupInputsRequest(const std::vector<uint8_t>& payload) {
  return SplitNames(
      std::string_view(reinterpret_cast<const char*>(payload.data()), payload.size()));
}

std::vector<uint8_t> EncodeRecipeReply(const RecipeReply& reply, PacketType request,
                                       int protocol_version) {
  BigEndianWriter writer;
  if (RecipeReplyHasId(request, protocol_version)) writer.U8(reply.recipe_id);
  writer.Bytes(JoinNames(reply.types));
  return Take(writer);
}

RecipeReply DecodeRecipeReply(const std::vector<uint8_t>& payload, PacketType request,
                              int protocol_version) {
  auto reader = ReaderFor(payload, "RTDE recipe setup reply");
  RecipeReply reply;
  if (RecipeReplyHasId(request, protocol_version)) reply.recipe_id = reader.U8();
  reply.types = SplitNames(reader.Rest());
  return reply;
}

std::vector<uint8_t> EncodeTextMessage(const TextMessage& message, int protocol_version) {
  BigEndianWriter writer;
  if (protocol_version >= 2) {
    if (message.message.size() > 255 || message.source.size() > 255) {
      throw std::invalid_argument("RTDE text message: message and source must be <= 255 bytes");
    }
    writer.U8(static_cast<uint8_t>(message.message.size()));
    writer.Bytes(message.message);
    writer.U8(static_cast<uint8_t>(message.source.size()));
    writer.Bytes(message.source);
    writer.U8(static_cast<uint8_t>(message.level));
  } else {
    writer.U8(static_cast<uint8_t>(message.level));
    writer.Bytes(message.message);
  }
  return Take(writer);
}

TextMessage DecodeTextMessage(const std::vector<uint8_t>& payload, int protocol_version) {
  auto reader = ReaderFor(payload, "RTDE text message");
  TextMessage message;
  uint8_t level = 0;
  if (protocol_version >= 2) {
    message.message = reader.Bytes(reader.U8());
    message.source = reader.Bytes(reader.U8());
    level = reader.U8();
    ExpectConsumed(reader, "RTDE text message");
  } else {
    level = reader.U8();
    message.message = reader.Rest();
  }
  if (level > 3) {
    throw std::runtime_error(fmt::format("RTDE text message: unknown level {}", level));
  }
  message.level = static_cast<MessageLevel>(level);
  return message;
}

std::vector<uint8_t> EncodeDataPackage(const DataPackage& package,
                                       const std::vector<ValueType>& types, int protocol_version) {
  if (package.values.size() != types.size()) {
    throw std::invalid_argument(fmt::format("RTDE data package: {} value(s) for a recipe of {}",
                                            package.values.size(), types.size()));
  }
  BigEndianWriter writer;
  if (protocol_version >= 2) writer.U8(package.recipe_id);
  for (size_t i = 0; i < types.size(); ++i) {
    const Value& value = package.values[i];
    if (TypeOf(value) != types[i]) {
      throw std::invalid_argument(fmt::format("RTDE data package: value {} is {}, recipe says {}",
                                              i, ValueTypeName(TypeOf(value)),
                                              ValueTypeName(types[i])));
    }
    std::visit(
        [&writer](const auto& v) {
          using T = std::decay_t<decltype(v)>;
          if constexpr (std::is_same_v<T, bool> || std::is_same_v<T, uint8_t>) {
            writer.U8(static_cast<uint8_t>(v));
          } else if constexpr (std::is_same_v<T, uint32_t>) {
            writer.U32(v);
          } else if constexpr (std::is_same_v<T, uint64_t>) {
            writer.U64(v);
          } else if constexpr (std::is_same_v<T, int32_t>) {
            writer.I32(v);
          } else if constexpr (std::is_same_v<T, double>) {
            writer.F64(v);
          } else if constexpr (std::is_same_v<T, std::array<double, 3>> ||
                               std::is_same_v<T, std::array<double, 6>>) {
            for (double x : v) writer.F64(x);
          } else if constexpr (std::is_same_v<T, std::array<int32_t, 6>>) {
            for (int32_t x : v) writer.I32(x);
          } else {
            for (uint32_t x : v) writer.U32(x);
          }
        },
        value);
  }
  return Take(writer);
}

DataPackage DecodeDataPackage(const std::vector<uint8_t>& payload,
                              const std::vector<ValueType>& types, int protocol_version) {
  auto reader = ReaderFor(payload, "RTDE data package");
  DataPackage package;
  if (protocol_version >= 2) package.recipe_id = reader.U8();
  package.values.reserve(types.size());
  for (ValueType type : types) {
    switch (type) {
      case ValueType::kBool:
        package.values.emplace_back(reader.U8() != 0);
        break;
      case ValueType::kUint8:
        package.values.emplace_back(reader.U8());
        break;
      case ValueType::kUint32:
        package.values.emplace_back(reader.U32());
        break;
      case ValueType::kUint64:
        package.values.emplace_back(reader.U64());
        break;
      case ValueType::kInt32:
        package.values.emplace_back(reader.I32());
        break;
      case ValueType::kDouble:
        package.values.emplace_back(reader.F64());
        break;
      case ValueType::kVector3d:
        package.values.emplace_back(ReadArray<double, 3>([&] { return reader.F64(); }));
        break;
      case ValueType::kVector6d:
        package.values.emplace_back(ReadArray<double, 6>([&] { return reader.F64(); }));
        break;
      case ValueType::kVector6Int32:
        package.values.emplace_back(ReadArray<int32_t, 6>([&] { return reader.I32(); }));
        break;
      case ValueType::kVector6Uint32:
        package.values.emplace_back(ReadArray<uint32_t, 6>([&] { return reader.U32(); }));
        break;
    }
  }
  ExpectConsumed(reader, "RTDE data package");
  return package;
}

std::string JoinNames(const std::vector<std::string>& names) {
  std::string joined;
  for (size_t i = 0; i < names.size(); ++i) {
    if (i > 0) joined += ',';
    joined += names[i];
  }
  return joined;
}

std::vector<std::string> SplitNames(std::string_view text) {
  std::vector<std::string> names;
  if (text.empty()) return names;
  size_t start = 0;
  while (true) {
    const size_t comma = text.find(',', start);
    names.emplace_back(
        text.substr(start, comma == std::string_view::npos ? text.npos : comma - start));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return names;
}

}  // namespace avc::robot::rtde
