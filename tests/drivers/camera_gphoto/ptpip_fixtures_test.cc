// Every case of fixtures/ptpip.json (PTP/IP packets assembled from libgphoto2, Wireshark's
// dissector and CIPA DC-X005 layouts, each case citing its source) through the emulator's codec:
// cut from a stream by TakePacket one byte at a time, decoded, compared field by field and
// re-encoded to the same bytes. Where we part ways with a source on purpose, the test asserts our
// behaviour so that a change shows up here.

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "sim/emulators/ptpip/byte_io.h"
#include "sim/emulators/ptpip/ptpip_packets.h"
#include "tests/support/fixture_file.h"

namespace avc::sim::ptp {
namespace {

using Bytes = std::vector<uint8_t>;
using testing::ExpectedFields;
using testing::ExpectField;

// Adding or removing fixture cases is a deliberate change: update this count with it.
constexpr size_t kFixtureCases = 22;

struct Case {
  ExpectedFields& expect;
  Bytes bytes;
  Packet packet;
};

// Feeds the bytes one at a time: no packet may come out before the last byte, then exactly one.
Packet TakeOnePacket(const Bytes& bytes) {
  Bytes stream;
  for (size_t i = 0; i < bytes.size(); ++i) {
    stream.push_back(bytes[i]);
    std::optional<Packet> packet = TakePacket(stream);
    if (!packet) continue;
    if (i + 1 < bytes.size()) {
      throw std::runtime_error("packet ended after " + std::to_string(i + 1) + " bytes");
    }
    EXPECT_TRUE(stream.empty());
    return std::move(*packet);
  }
  throw std::runtime_error("TakePacket wants more bytes than the fixture has");
}

void ExpectReencoded(const Case& c, const Bytes& bytes) {
  EXPECT_EQ(bytes, c.bytes) << "re-encoding gives other bytes";
}

// guid and data bytes are hex strings in the fixture.
template <class Range>
void ExpectHex(ExpectedFields& expect, const std::string& key, const Range& got) {
  EXPECT_EQ(Bytes(std::begin(got), std::end(got)),
            testing::ParseHex(expect[key].get<std::string>()))
      << key;
}

void CheckInitCommandRequest(Case& c) {
  const InitCommandRequest m = DecodeInitCommandRequest(c.packet.payload);
  ExpectHex(c.expect, "guid", m.guid);
  ExpectField(c.expect, "host_name", m.host_name);
  ExpectField(c.expect, "version", m.version);
  ExpectReencoded(c, Encode(m));
}

void CheckInitCommandAck(Case& c) {
  const InitCommandAck m = DecodeInitCommandAck(c.packet.payload);
  ExpectField(c.expect, "connection_number", m.connection_number);
  ExpectHex(c.expect, "guid", m.guid);
  ExpectField(c.expect, "name", m.name);
  ExpectField(c.expect, "version", m.version);
  ExpectReencoded(c, Encode(m));
}

void CheckInitEventRequest(Case& c) {
  const InitEventRequest m = DecodeInitEventRequest(c.packet.payload);
  ExpectField(c.expect, "connection_number", m.connection_number);
  ExpectReencoded(c, Encode(m));
}

void CheckEmpty(Case& c) {
  ExpectField(c.expect, "payload_length", c.packet.payload.size());
  switch (c.packet.type) {
    case PacketType::kInitEventAck:
      return ExpectReencoded(c, EncodeInitEventAck());
    case PacketType::kPing:
      return ExpectReencoded(c, EncodePing());
    case PacketType::kPong:
      return ExpectReencoded(c, EncodePong());
    default:
      ADD_FAILURE() << PacketTypeName(c.packet.type) << " is not an empty packet";
  }
}

void CheckOperationRequest(Case& c) {
  const OperationRequest m = DecodeOperationRequest(c.packet.payload);
  ExpectField(c.expect, "data_phase", m.data_phase);
  ExpectField(c.expect, "code", m.code);
  ExpectField(c.expect, "transaction_id", m.transaction_id);
  ExpectField(c.expect, "params", m.params);
  ExpectReencoded(c, Encode(m));
}

void CheckOperationResponse(Case& c) {
  const OperationResponse m = DecodeOperationResponse(c.packet.payload);
  ExpectField(c.expect, "code", m.code);
  ExpectField(c.expect, "transaction_id", m.transaction_id);
  ExpectField(c.expect, "params", m.params);
  ExpectReencoded(c, Encode(m));
}

void CheckEvent(Case& c) {
  const EventMessage m = DecodeEvent(c.packet.payload);
  ExpectField(c.expect, "code", m.code);
  ExpectField(c.expect, "transaction_id", m.transaction_id);
  ExpectField(c.expect, "params", m.params);
  ExpectReencoded(c, Encode(m));
}

void CheckStartData(Case& c) {
  const StartData m = DecodeStartData(c.packet.payload);
  ExpectField(c.expect, "transaction_id", m.transaction_id);
  ExpectField(c.expect, "total_length", m.total_length);
  if (c.expect.Has("total_length_hex")) {
    EXPECT_EQ(m.total_length,
              testing::ParseHexU64(c.expect["total_length_hex"].get<std::string>()));
  }
  ExpectReencoded(c, Encode(m));
}

void CheckDataChunk(Case& c) {
  const DataChunk m = DecodeDataChunk(c.packet.payload);
  ExpectField(c.expect, "transaction_id", m.transaction_id);
  ExpectHex(c.expect, "bytes", m.bytes);
  ExpectReencoded(c, Encode(m, c.packet.type == PacketType::kEndData));
}

// Our refusal of a layout a source uses: PtpDecodeError naming the field that is missing. The
// fields before it cannot come back from a decoder that threw, so they are acknowledged unread.
template <class Decode>
void ExpectRefusedAt(Case& c, Decode decode, const std::string& field) {
  try {
    decode(c.packet.payload);
    ADD_FAILURE() << "accepted; we refuse this layout";
  } catch (const PtpDecodeError& e) {
    EXPECT_NE(std::string(e.what()).find("'" + field + "'"), std::string::npos) << e.what();
  }
}

// init_command_request_without_version_atotto: atotto/ptpip and PTPIP.TXT end the request after
// the name; we follow CIPA DC-X005 and libgphoto2, which append the protocol version.
void RefusesRequestWithoutVersion(Case& c) {
  ExpectRefusedAt(c, DecodeInitCommandRequest, "version");
  c.expect.Acknowledge({"guid", "host_name"});
}

// init_command_ack_without_version_atotto: the same for the ack (libgphoto2 itself would accept
// it, but the emulator only decodes acks in tests; it sends the CIPA form).
void RefusesAckWithoutVersion(Case& c) {
  ExpectRefusedAt(c, DecodeInitCommandAck, "version");
  c.expect.Acknowledge({"connection_number", "guid", "name"});
}

// start_data_legacy_32bit_length: libgphoto2 of 2006 wrote a 4-byte total length; CIPA and the
// current libgphoto2 write 8, which is all we accept.
void RefusesLegacyStartData(Case& c) {
  ExpectRefusedAt(c, DecodeStartData, "total length");
  c.expect.Acknowledge({"transaction_id", "total_length"});
}

// Frames the case's hex, checks the header against expect length/type, then runs `check`.
testing::CaseCheck Framed(void (*check)(Case&)) {
  return [check](const nlohmann::json& json, ExpectedFields& expect) {
    Case c{expect, testing::ParseHex(json.at("hex").get<std::string>()), {}};
    c.packet = TakeOnePacket(c.bytes);
    ExpectField(c.expect, "length", c.bytes.size());
    ExpectField(c.expect, "type", static_cast<uint32_t>(c.packet.type));
    check(c);
  };
}

testing::CaseChecks Checks() {
  testing::CaseChecks checks;
  checks.by_packet = {
      {"InitCommandRequest (1)", Framed(CheckInitCommandRequest)},
      {"InitCommandRequest (1) without protocol version", Framed(CheckInitCommandRequest)},
      {"InitCommandRequest (1), 2006 libgphoto2 field order", Framed(CheckInitCommandRequest)},
      {"InitCommandAck (2)", Framed(CheckInitCommandAck)},
      {"InitCommandAck (2) without protocol version", Framed(CheckInitCommandAck)},
      {"InitEventRequest (3)", Framed(CheckInitEventRequest)},
      {"InitEventAck (4)", Framed(CheckEmpty)},
      {"OperationRequest (6) OpenSession", Framed(CheckOperationRequest)},
      {"OperationRequest (6) GetDeviceInfo", Framed(CheckOperationRequest)},
      {"OperationResponse (7) OK", Framed(CheckOperationResponse)},
      {"OperationResponse (7) with 5 parameters", Framed(CheckOperationResponse)},
      {"Event (8) ObjectAdded", Framed(CheckEvent)},
      {"StartData (9)", Framed(CheckStartData)},
      {"StartData (9), total length > 32 bits", Framed(CheckStartData)},
      {"StartData (9), length unknown", Framed(CheckStartData)},
      {"StartData (9), legacy 16-byte form", Framed(CheckStartData)},
      {"Data (10)", Framed(CheckDataChunk)},
      {"EndData (12)", Framed(CheckDataChunk)},
      {"EndData (12) with no payload", Framed(CheckDataChunk)},
      {"Ping (13)", Framed(CheckEmpty)},
      {"Pong (14)", Framed(CheckEmpty)},
  };
  checks.disagreements = {
      {"init_command_request_without_version_atotto", Framed(RefusesRequestWithoutVersion)},
      {"init_command_ack_without_version_atotto", Framed(RefusesAckWithoutVersion)},
      {"start_data_legacy_32bit_length", Framed(RefusesLegacyStartData)},
  };
  checks.is_refusal = [](const std::exception& e) {
    return dynamic_cast<const PtpDecodeError*>(&e) != nullptr;
  };
  return checks;
}

TEST(PtpIpFixtures, EveryCaseDecodesAndReencodesAsItsSourceSays) {
  const nlohmann::json file =
      testing::LoadFixtureFile("tests/drivers/camera_gphoto/fixtures/ptpip.json");
  EXPECT_EQ(file["cases"].size(), kFixtureCases);
  EXPECT_EQ(testing::CheckFixtureCases(file, Checks()), file["cases"].size());
}

}  // namespace
}  // namespace avc::sim::ptp
