// RTDE codec: round trips and byte vectors written by hand from the protocol description
// (uint16 size incl. header, uint8 type, big-endian payload).

#include "drivers/robot/protocol/rtde_protocol.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace avc::robot::rtde {
namespace {

using Bytes = std::vector<uint8_t>;

Bytes Concat(const Bytes& a, const Bytes& b) {
  Bytes out = a;
  out.insert(out.end(), b.begin(), b.end());
  return out;
}

Bytes Ascii(std::string_view text) { return Bytes(text.begin(), text.end()); }

TEST(RtdeProtocol, ProtocolVersionRequestMatchesHandWrittenBytes) {
  const Bytes expected = {0x00, 0x05, 'V', 0x00, 0x02};
  EXPECT_EQ(EncodePacket(PacketType::kRequestProtocolVersion, EncodeProtocolVersionRequest(2)),
            expected);
  EXPECT_EQ(DecodeProtocolVersionRequest({0x00, 0x01}), 1);
}

TEST(RtdeProtocol, AcceptedReplyDecodes) {
  EXPECT_TRUE(DecodeAccepted({0x01}, "V reply"));
  EXPECT_FALSE(DecodeAccepted({0x00}, "V reply"));
  EXPECT_THROW(DecodeAccepted({}, "V reply"), std::runtime_error);
  EXPECT_THROW(DecodeAccepted({0x01, 0x00}, "V reply"), std::runtime_error);
}

TEST(RtdeProtocol, ControllerVersionMatchesHandWrittenBytes) {
  // 3.15.7 build 106331 = 0x00019F5B.
  const Bytes payload = {0, 0, 0, 3, 0, 0, 0, 15, 0, 0, 0, 7, 0x00, 0x01, 0x9F, 0x5B};
  const ControllerVersion version = DecodeControllerVersion(payload);
  EXPECT_EQ(version, (ControllerVersion{3, 15, 7, 106331}));
  EXPECT_EQ(EncodeControllerVersion(version), payload);
  EXPECT_EQ(version.ToString(), "3.15.7.106331");
}

TEST(RtdeProtocol, SetupOutputsV2CarriesFrequencyThenNames) {
  // 125.0 = 0x405F400000000000.
  const Bytes expected_payload =
      Concat({0x40, 0x5F, 0x40, 0, 0, 0, 0, 0}, Ascii("timestamp,actual_q"));
  const SetupOutputsRequest request{125.0, {"timestamp", "actual_q"}};
  EXPECT_EQ(EncodeSetupOutputsRequest(request, 2), expected_payload);
  const auto decoded = DecodeSetupOutputsRequest(expected_payload, 2);
  EXPECT_EQ(decoded.frequency, 125.0);
  EXPECT_EQ(decoded.names, request.names);
  // Version 1 has no frequency field.
  EXPECT_EQ(EncodeSetupOutputsRequest(request, 1), Ascii("timestamp,actual_q"));
  EXPECT_EQ(DecodeSetupOutputsRequest(Ascii("timestamp"), 1).names,
            std::vector<std::string>{"timestamp"});
}

TEST(RtdeProtocol, NameListAbove2048BytesIsRefused) {
  std::vector<std::string> names(300, "actual_q");  // 300 * 9 - 1 bytes
  EXPECT_THROW(EncodeSetupOutputsRequest({125.0, names}, 2), std::invalid_argument);
  EXPECT_THROW(EncodeSetupInputsRequest(names), std::invalid_argument);
}

TEST(RtdeProtocol, RecipeReplyKeepsNotFoundAndInUseMarkers) {
  const Bytes payload = Concat({0x01}, Ascii("DOUBLE,NOT_FOUND,IN_USE"));
  const RecipeReply reply = DecodeRecipeReply(payload, PacketType::kSetupInputs, 2);
  EXPECT_EQ(reply.recipe_id, 1);
  EXPECT_EQ(reply.types, (std::vector<std::string>{"DOUBLE", "NOT_FOUND", "IN_USE"}));
  EXPECT_EQ(EncodeRecipeReply(reply, PacketType::kSetupInputs, 2), payload);
  EXPECT_EQ(ParseValueType("VECTOR6D"), ValueType::kVector6d);
  EXPECT_EQ(ParseValueType("NOT_FOUND"), std::nullopt);
  EXPECT_EQ(ParseValueType("IN_USE"), std::nullopt);
}

// A v1 'O' reply is the types alone; 'I' replies keep their recipe id at v1.
TEST(RtdeProtocol, RecipeReplyHasNoIdOnlyForVersion1Outputs) {
  const Bytes types = Ascii("DOUBLE,VECTOR6D");
  const RecipeReply outputs_v1 = DecodeRecipeReply(types, PacketType::kSetupOutputs, 1);
  EXPECT_EQ(outputs_v1.recipe_id, 0);
  EXPECT_EQ(outputs_v1.types, (std::vector<std::string>{"DOUBLE", "VECTOR6D"}));
  EXPECT_EQ(EncodeRecipeReply({7, outputs_v1.types}, PacketType::kSetupOutputs, 1), types);
  const Bytes with_id = Concat({0x02}, types);
  EXPECT_EQ(DecodeRecipeReply(with_id, PacketType::kSetupOutputs, 2).recipe_id, 2);
  EXPECT_EQ(DecodeRecipeReply(with_id, PacketType::kSetupInputs, 1).recipe_id, 2);
  EXPECT_EQ(EncodeRecipeReply({2, outputs_v1.types}, PacketType::kSetupInputs, 1), with_id);
  EXPECT_THROW(DecodeRecipeReply(with_id, PacketType::kStart, 2), std::invalid_argument);
}

TEST(RtdeProtocol, SetupInputsRoundTrip) {
  const std::vector<std::string> names = {"input_int_register_24", "speed_slider_fraction"};
  const Bytes payload = EncodeSetupInputsRequest(names);
  EXPECT_EQ(payload, Ascii("input_int_register_24,speed_slider_fraction"));
  EXPECT_EQ(DecodeSetupInputsRequest(payload), names);
}

TEST(RtdeProtocol, TextMessageV2AndV1Layouts) {
  const TextMessage message{"hi", "src", MessageLevel::kError};
  const Bytes v2 = {2, 'h', 'i', 3, 's', 'r', 'c', 1};
  EXPECT_EQ(EncodeTextMessage(message, 2), v2);
  EXPECT_EQ(DecodeTextMessage(v2, 2), message);
  const Bytes v1 = {2, 'o', 'k'};
  const TextMessage decoded = DecodeTextMessage(v1, 1);
  EXPECT_EQ(decoded.level, MessageLevel::kWarning);
  EXPECT_EQ(decoded.message, "ok");
  EXPECT_THROW(DecodeTextMessage({5, 'a'}, 2), std::runtime_error);
}

TEST(RtdeProtocol, DataPackageMatchesHandWrittenBytes) {
  // recipe 1: DOUBLE 1.5 (0x3FF8...), INT32 -1, UINT32 2, BOOL true.
  const std::vector<ValueType> types = {ValueType::kDouble, ValueType::kInt32, ValueType::kUint32,
                                        ValueType::kBool};
  const Bytes payload = {0x01, 0x3F, 0xF8, 0, 0, 0, 0, 0, 0, 0xFF, 0xFF, 0xFF, 0xFF, 0, 0, 0, 2, 1};
  const DataPackage package = DecodeDataPackage(payload, types, 2);
  EXPECT_EQ(package.recipe_id, 1);
  ASSERT_EQ(package.values.size(), 4u);
  EXPECT_EQ(std::get<double>(package.values[0]), 1.5);
  EXPECT_EQ(std::get<int32_t>(package.values[1]), -1);
  EXPECT_EQ(std::get<uint32_t>(package.values[2]), 2u);
  EXPECT_EQ(std::get<bool>(package.values[3]), true);
  EXPECT_EQ(EncodeDataPackage(package, types, 2), payload);
  // Version 1 omits the recipe id.
  const Bytes v1(payload.begin() + 1, payload.end());
  EXPECT_EQ(EncodeDataPackage(package, types, 1), v1);
  EXPECT_EQ(std::get<int32_t>(DecodeDataPackage(v1, types, 1).values[1]), -1);
}

TEST(RtdeProtocol, DataPackageRoundTripsEveryVectorType) {
  const std::vector<ValueType> types = {ValueType::kVector3d,     ValueType::kVector6d,
                                        ValueType::kVector6Int32, ValueType::kVector6Uint32,
                                        ValueType::kUint64,       ValueType::kUint8};
  DataPackage package;
  package.recipe_id = 7;
  package.values = {std::array<double, 3>{1, -2, 3.25},
                    std::array<double, 6>{0.1, 0.2, -0.3, 4, 5, 6},
                    std::array<int32_t, 6>{-1, 2, -3, 4, -5, 6},
                    std::array<uint32_t, 6>{1, 2, 3, 4, 5, 0xFFFFFFFF},
                    uint64_t{0x0102030405060708},
                    uint8_t{9}};
  const Bytes payload = EncodeDataPackage(package, types, 2);
  EXPECT_EQ(payload.size(), 1u + 24 + 48 + 24 + 24 + 8 + 1);
  const DataPackage decoded = DecodeDataPackage(payload, types, 2);
  EXPECT_EQ(decoded.recipe_id, 7);
  EXPECT_EQ(decoded.values, package.values);
}

TEST(RtdeProtocol, DataPackageRejectsMismatches) {
  const std::vector<ValueType> types = {ValueType::kDouble};
  EXPECT_THROW(EncodeDataPackage({1, {int32_t{1}}}, types, 2), std::invalid_argument);
  EXPECT_THROW(EncodeDataPackage({1, {}}, types, 2), std::invalid_argument);
  EXPECT_THROW(DecodeDataPackage({1, 0, 0}, types, 2), std::runtime_error);
  EXPECT_THROW(DecodeDataPackage(Bytes(10, 0), types, 2), std::runtime_error);
}

TEST(RtdeProtocol, FramerSplitsAcrossArbitraryChunks) {
  const Bytes first = EncodePacket(PacketType::kStart, EncodeAccepted(true));
  const Bytes second =
      EncodePacket(PacketType::kTextMessage, EncodeTextMessage({"x", "y", MessageLevel::kInfo}, 2));
  const Bytes stream = Concat(first, second);
  PacketFramer framer;
  std::vector<Packet> packets;
  for (uint8_t byte : stream) {  // one byte at a time: the worst fragmentation
    framer.Append(&byte, 1);
    while (auto packet = framer.Next()) packets.push_back(*packet);
  }
  ASSERT_EQ(packets.size(), 2u);
  EXPECT_EQ(packets[0].type, 'S');
  EXPECT_EQ(packets[0].payload, Bytes{1});
  EXPECT_EQ(packets[1].type, 'M');
  EXPECT_EQ(DecodeTextMessage(packets[1].payload, 2).message, "x");
  EXPECT_EQ(framer.buffered(), 0u);
}

TEST(RtdeProtocol, FramerRejectsImpossibleSize) {
  PacketFramer framer;
  const Bytes bad = {0x00, 0x02, 'S'};
  framer.Append(bad.data(), bad.size());
  EXPECT_THROW(framer.Next(), std::runtime_error);
}

TEST(RtdeProtocol, OversizedPacketIsRefused) {
  EXPECT_THROW(EncodePacket(PacketType::kDataPackage, Bytes(kMaxPacketSize, 0)),
               std::invalid_argument);
}

}  // namespace
}  // namespace avc::robot::rtde
