// Every case of fixtures/rtde.json (bytes from UR's client library tests, the RTDE Python client
// and the RTDE guide, each case citing its source): framed by PacketFramer one byte at a time,
// decoded, compared field by field and re-encoded to the same bytes. Where we part ways with a
// source on purpose, the test asserts our behaviour so that a change shows up here.

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "drivers/robot/protocol/rtde_protocol.h"
#include "tests/support/fixture_file.h"

namespace avc::robot::rtde {
namespace {

using Bytes = std::vector<uint8_t>;
using testing::ExpectedFields;
using testing::ExpectField;
using testing::ExpectFieldOr;

// Adding or removing fixture cases is a deliberate change: update this count with it.
constexpr size_t kFixtureCases = 35;

// One case after framing: its bytes, the packet PacketFramer cut from them and the expect fields.
struct Case {
  const nlohmann::json& json;
  ExpectedFields& expect;
  Bytes bytes;
  Packet packet;

  int ProtocolVersion() const { return json.at("protocol_version").get<int>(); }
  PacketType Type() const { return static_cast<PacketType>(packet.type); }
};

// Feeds the bytes one at a time: no packet may come out before the last byte, then exactly one.
Packet FrameOnePacket(const Bytes& bytes) {
  PacketFramer framer;
  for (size_t i = 0; i + 1 < bytes.size(); ++i) {
    framer.Append(&bytes[i], 1);
    if (framer.Next())
      throw std::runtime_error("packet ended after " + std::to_string(i + 1) + " bytes");
  }
  if (!bytes.empty()) framer.Append(&bytes.back(), 1);
  std::optional<Packet> packet = framer.Next();
  if (!packet) throw std::runtime_error("the framer wants more bytes than the fixture has");
  EXPECT_EQ(framer.buffered(), 0u);
  return std::move(*packet);
}

void ExpectReencoded(const Case& c, const Bytes& payload) {
  EXPECT_EQ(EncodePacket(c.Type(), payload), c.bytes) << "re-encoding gives other bytes";
}

void CheckEmpty(Case& c) {
  ExpectField(c.expect, "payload_length", c.packet.payload.size());
  ExpectReencoded(c, {});
}

void CheckVersionRequest(Case& c) {
  const uint16_t version = DecodeProtocolVersionRequest(c.packet.payload);
  ExpectField(c.expect, "version", version);
  ExpectReencoded(c, EncodeProtocolVersionRequest(version));
}

void CheckAccepted(Case& c) {
  const bool accepted = DecodeAccepted(c.packet.payload, "fixture reply");
  ExpectField(c.expect, "accepted", accepted);
  ExpectReencoded(c, EncodeAccepted(accepted));
}

void CheckControllerVersion(Case& c) {
  const ControllerVersion version = DecodeControllerVersion(c.packet.payload);
  ExpectField(c.expect, "major", version.major);
  ExpectField(c.expect, "minor", version.minor);
  ExpectField(c.expect, "bugfix", version.bugfix);
  ExpectField(c.expect, "build", version.build);
  ExpectReencoded(c, EncodeControllerVersion(version));
}

void CheckSetupOutputsRequest(Case& c) {
  const SetupOutputsRequest request =
      DecodeSetupOutputsRequest(c.packet.payload, c.ProtocolVersion());
  ExpectFieldOr(c.expect, "frequency", request.frequency, SetupOutputsRequest{}.frequency);
  ExpectField(c.expect, "names", request.names);
  ExpectReencoded(c, EncodeSetupOutputsRequest(request, c.ProtocolVersion()));
}

void CheckSetupInputsRequest(Case& c) {
  const std::vector<std::string> names = DecodeSetupInputsRequest(c.packet.payload);
  ExpectField(c.expect, "names", names);
  ExpectReencoded(c, EncodeSetupInputsRequest(names));
}

void CheckRecipeReply(Case& c, PacketType request, int protocol_version) {
  SCOPED_TRACE("decoded as protocol version " + std::to_string(protocol_version));
  const RecipeReply reply = DecodeRecipeReply(c.packet.payload, request, protocol_version);
  ExpectFieldOr(c.expect, "recipe_id", reply.recipe_id, 0);
  ExpectField(c.expect, "types", reply.types);
  ExpectReencoded(c, EncodeRecipeReply(reply, request, protocol_version));
}

void CheckSetupOutputsReply(Case& c) {
  CheckRecipeReply(c, PacketType::kSetupOutputs, c.ProtocolVersion());
}

// 'I' replies have one layout at both versions, so a case without a version is checked at both.
void CheckSetupInputsReply(Case& c) {
  if (c.json.contains("protocol_version")) {
    CheckRecipeReply(c, PacketType::kSetupInputs, c.ProtocolVersion());
    return;
  }
  for (const int version : {1, 2}) CheckRecipeReply(c, PacketType::kSetupInputs, version);
}

std::vector<ValueType> RecipeTypes(const Case& c) {
  std::vector<ValueType> types;
  for (const auto& name : c.json.at("recipe_types")) {
    const std::optional<ValueType> type = ParseValueType(name.get<std::string>());
    if (!type) throw std::invalid_argument("unknown recipe type " + name.dump());
    types.push_back(*type);
  }
  return types;
}

void ExpectValues(Case& c, const std::vector<Value>& values) {
  const nlohmann::json& want = c.expect["values"];
  ASSERT_EQ(values.size(), want.size());
  for (size_t i = 0; i < values.size(); ++i) {
    SCOPED_TRACE("value " + std::to_string(i));
    ExpectedFields value(want[i]);
    EXPECT_EQ(std::string(ValueTypeName(TypeOf(values[i]))), value["type"].get<std::string>());
    std::visit([&value](const auto& got) { ExpectField(value, "value", got); }, values[i]);
    EXPECT_EQ(value.Unchecked(), "");
  }
}

void CheckDataPackage(Case& c) {
  const std::vector<ValueType> types = RecipeTypes(c);
  const DataPackage package = DecodeDataPackage(c.packet.payload, types, c.ProtocolVersion());
  ExpectFieldOr(c.expect, "recipe_id", package.recipe_id, 0);
  ExpectValues(c, package.values);
  ExpectReencoded(c, EncodeDataPackage(package, types, c.ProtocolVersion()));
}

void CheckTextMessage(Case& c) {
  const TextMessage message = DecodeTextMessage(c.packet.payload, c.ProtocolVersion());
  ExpectField(c.expect, "message", message.message);
  ExpectField(c.expect, "source", message.source);
  ExpectField(c.expect, "level", static_cast<int>(message.level));
  ExpectReencoded(c, EncodeTextMessage(message, c.ProtocolVersion()));
}

// data_package_v2_trailing_bytes: the UR client library ignores bytes after the recipe's values;
// we refuse such a package, and without the extra bytes it decodes to the fixture's values.
void RefusesTrailingBytes(Case& c) {
  const std::vector<ValueType> types = RecipeTypes(c);
  EXPECT_THROW(DecodeDataPackage(c.packet.payload, types, c.ProtocolVersion()), std::runtime_error);
  const size_t trailing = c.expect["trailing_bytes"].get<size_t>();
  ASSERT_LE(trailing, c.packet.payload.size());
  const Bytes values_only(c.packet.payload.begin(),
                          c.packet.payload.end() - static_cast<ptrdiff_t>(trailing));
  const DataPackage package = DecodeDataPackage(values_only, types, c.ProtocolVersion());
  ExpectFieldOr(c.expect, "recipe_id", package.recipe_id, 0);
  ExpectValues(c, package.values);
}

// Frames the case's hex, checks the header against expect size/type, then runs `check`.
testing::CaseCheck Framed(void (*check)(Case&)) {
  return [check](const nlohmann::json& json, ExpectedFields& expect) {
    Case c{json, expect, testing::ParseHex(json.at("hex").get<std::string>()), {}};
    c.packet = FrameOnePacket(c.bytes);
    ExpectField(c.expect, "size", c.bytes.size());
    ExpectField(c.expect, "type", c.packet.type);
    check(c);
  };
}

testing::CaseChecks Checks() {
  testing::CaseChecks checks;
  checks.by_packet = {
      {"V request", Framed(CheckVersionRequest)},
      {"V reply", Framed(CheckAccepted)},
      {"v request", Framed(CheckEmpty)},
      {"v reply", Framed(CheckControllerVersion)},
      {"O request v2 (frequency + names)", Framed(CheckSetupOutputsRequest)},
      {"O request v1 (names only)", Framed(CheckSetupOutputsRequest)},
      {"O reply v2 (recipe id + types)", Framed(CheckSetupOutputsReply)},
      {"O reply v2 with NOT_FOUND", Framed(CheckSetupOutputsReply)},
      {"O reply v1 (types only, no recipe id)", Framed(CheckSetupOutputsReply)},
      {"I request (names)", Framed(CheckSetupInputsRequest)},
      {"I reply (recipe id + types)", Framed(CheckSetupInputsReply)},
      {"I reply with IN_USE", Framed(CheckSetupInputsReply)},
      {"S request", Framed(CheckEmpty)},
      {"S reply", Framed(CheckAccepted)},
      {"P request", Framed(CheckEmpty)},
      {"P reply", Framed(CheckAccepted)},
      {"U data package v2 (output)", Framed(CheckDataPackage)},
      {"U data package v1 (no recipe id)", Framed(CheckDataPackage)},
      {"U data package v2 (input)", Framed(CheckDataPackage)},
      {"U data package v1 (input, no recipe id)", Framed(CheckDataPackage)},
      {"U data package v2 (all 10 wire types)", Framed(CheckDataPackage)},
      {"U data package v2 longer than its recipe", Framed(CheckDataPackage)},
      {"M text message v2", Framed(CheckTextMessage)},
      {"M text message v1 (level + message)", Framed(CheckTextMessage)},
  };
  checks.disagreements = {{"data_package_v2_trailing_bytes", Framed(RefusesTrailingBytes)}};
  return checks;
}

TEST(RtdeFixtures, EveryCaseDecodesAndReencodesAsItsSourceSays) {
  const nlohmann::json file =
      testing::LoadFixtureFile("tests/drivers/robot/protocol/fixtures/rtde.json");
  EXPECT_EQ(file["cases"].size(), kFixtureCases);
  EXPECT_EQ(testing::CheckFixtureCases(file, Checks()), file["cases"].size());
}

}  // namespace
}  // namespace avc::robot::rtde
