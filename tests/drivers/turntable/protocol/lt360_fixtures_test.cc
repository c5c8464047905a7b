// Every case of fixtures/lt360.json (reply forms from the LinearX LT360 manuals, each case citing
// its page): split into replies by FrameSplitter, parsed, compared with the fixture and, where
// the emulator has an encoder, formatted back to the same text.

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>

#include "drivers/turntable/protocol/lt360_protocol.h"
#include "tests/support/fixture_file.h"

namespace avc::turntable {
namespace {

using testing::ExpectedFields;
using testing::ExpectField;

// Adding or removing fixture cases is a deliberate change: update this count with it.
constexpr size_t kFixtureCases = 20;

// Replies the device may write in a form other than ours: FormatPositionTenths writes "+45.0" and
// MotionName "CCW". These only have to format to text that parses back to the same value.
const std::map<std::string, std::string>& NonCanonicalReplies() {
  static const std::map<std::string, std::string> replies = {
      {"position_zero_padded", "the manual's +nnn.n may be zero-padded"},
      {"position_zero_nul_terminated", "the manual's +nnn.n may be zero-padded"},
      {"position_unsigned_zero", "the manual writes the bounds without a sign"},
      {"moving_lowercase", "replies may come in lower case"},
  };
  return replies;
}

// The frames FrameSplitter yields for the case's text; what stays pending must match too.
std::vector<std::string> Frames(const nlohmann::json& json, ExpectedFields& expect) {
  FrameSplitter splitter;
  splitter.Feed(json.at("text").get<std::string>());
  std::vector<std::string> frames;
  while (std::optional<std::string> frame = splitter.Next()) frames.push_back(*frame);
  ExpectField(expect, "frames", frames);
  const std::string pending = expect.Has("pending") ? expect["pending"].get<std::string>() : "";
  EXPECT_EQ(splitter.pending_bytes(), pending.size());
  if (!pending.empty()) {
    splitter.Feed("\r");
    EXPECT_EQ(splitter.Next(), pending) << "pending bytes";
  }
  return frames;
}

// The single reply of a case; the re-encoded text must equal it unless NonCanonicalReplies()
// lists the case.
std::string OneFrame(const nlohmann::json& json, ExpectedFields& expect) {
  const std::vector<std::string> frames = Frames(json, expect);
  if (frames.size() != 1) throw std::runtime_error("expected exactly one reply");
  return frames.front();
}

void ExpectReencoded(const nlohmann::json& json, const std::string& frame,
                     const std::string& ours) {
  if (NonCanonicalReplies().count(json.at("name").get<std::string>()) == 0) {
    EXPECT_EQ(ours, frame) << "re-encoding gives other text";
  }
}

void CheckPosition(const nlohmann::json& json, ExpectedFields& expect) {
  const std::string frame = OneFrame(json, expect);
  const int tenths = ParsePositionTenths(frame);  // throws for the "error" cases
  ExpectField(expect, "tenths", tenths);
  const std::string ours = FormatPositionTenths(tenths);
  EXPECT_EQ(ParsePositionTenths(ours), tenths);
  ExpectReencoded(json, frame, ours);
}

void CheckMotion(const nlohmann::json& json, ExpectedFields& expect) {
  const std::string frame = OneFrame(json, expect);
  const Motion motion = ParseMotion(frame);  // throws for the "error" cases
  const std::string ours = MotionName(motion);
  ExpectField(expect, "motion", ours);
  EXPECT_EQ(ParseMotion(ours), motion);
  ExpectReencoded(json, frame, ours);
}

void CheckStream(const nlohmann::json& json, ExpectedFields& expect) { Frames(json, expect); }

testing::CaseChecks Checks() {
  testing::CaseChecks checks;
  checks.by_packet = {
      {"Get Position reply", CheckPosition},
      {"Get Position reply (malformed)", CheckPosition},
      {"Get Position reply (empty)", CheckPosition},
      {"Get Moving reply", CheckMotion},
      {"Get Moving reply (lower case)", CheckMotion},
      {"Get Moving reply (malformed)", CheckMotion},
      {"byte stream with two replies", CheckStream},
      {"byte stream without terminator", CheckStream},
  };
  // The manual's "RS232 Invalid Return" is InvalidReply; any other exception is a bug.
  checks.is_refusal = [](const std::exception& e) {
    return dynamic_cast<const InvalidReply*>(&e) != nullptr;
  };
  return checks;
}

TEST(Lt360Fixtures, EveryCaseParsesAsTheManualSays) {
  const nlohmann::json file =
      testing::LoadFixtureFile("tests/drivers/turntable/protocol/fixtures/lt360.json");
  EXPECT_EQ(file["cases"].size(), kFixtureCases);
  EXPECT_EQ(testing::CheckFixtureCases(file, Checks()), file["cases"].size());
  // Every exemption from byte-exact re-encoding names a case the file still has.
  for (const auto& [name, why] : NonCanonicalReplies()) {
    EXPECT_TRUE(
        std::any_of(file["cases"].begin(), file["cases"].end(),
                    [&name = name](const nlohmann::json& c) { return c.at("name") == name; }))
        << name << " (" << why << ") is no longer a fixture case";
  }
}

}  // namespace
}  // namespace avc::turntable
