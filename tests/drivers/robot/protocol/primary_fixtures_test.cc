// Every case of fixtures/primary.json (UR client library test captures, python-urx and UR manual
// layouts, each case citing its source): framed by PackageFramer one byte at a time, decoded,
// compared field by field and re-encoded where we have an encoder. Where we part ways with a
// source on purpose, the test asserts our behaviour so that a change shows up here.

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>

#include "drivers/robot/protocol/big_endian.h"
#include "drivers/robot/protocol/primary_protocol.h"
#include "drivers/robot/protocol/primary_robot_state.h"
#include "tests/support/fixture_file.h"

namespace avc::robot::primary {
namespace {

using Bytes = std::vector<uint8_t>;
using testing::ExpectedFields;
using testing::ExpectField;
using testing::ExpectFieldOr;

// Adding or removing fixture cases is a deliberate change: update this count with it.
constexpr size_t kFixtureCases = 9;

struct Case {
  ExpectedFields& expect;
  Bytes bytes;
  Package package;
};

// Feeds the bytes one at a time: no package may come out before the last byte, then exactly one.
Package FrameOnePackage(const Bytes& bytes) {
  PackageFramer framer;
  for (size_t i = 0; i + 1 < bytes.size(); ++i) {
    framer.Append(&bytes[i], 1);
    if (framer.Next()) throw std::runtime_error("package ended after " + std::to_string(i + 1));
  }
  if (!bytes.empty()) framer.Append(&bytes.back(), 1);
  std::optional<Package> package = framer.Next();
  if (!package) throw std::runtime_error("the framer wants more bytes than the fixture has");
  return std::move(*package);
}

// The object under `key`, marked compared; nullptr when the fixture leaves it out or gives null.
const nlohmann::json* Member(ExpectedFields& expect, const std::string& key) {
  if (!expect.Has(key) || expect[key].is_null()) return nullptr;
  return &expect[key];
}

// --- ROBOT_MESSAGE ----------------------------------------------------------------------------

void ExpectRobotMessage(ExpectedFields& want, const RobotMessage& got) {
  const RobotMessage defaults;
  ExpectField(want, "timestamp", got.timestamp);
  ExpectField(want, "source", got.source);
  ExpectField(want, "message_type", got.message_type);
  ExpectFieldOr(want, "line", got.line, defaults.line);
  ExpectFieldOr(want, "column", got.column, defaults.column);
  ExpectField(want, "text", got.text);
}

void ExpectVersionMessage(ExpectedFields& want, const VersionMessage& got) {
  ExpectField(want, "project_name", got.project_name);
  ExpectField(want, "major", got.major);
  ExpectField(want, "minor", got.minor);
  ExpectField(want, "bugfix", got.bugfix);
  ExpectField(want, "build", got.build);
  ExpectField(want, "build_date", got.build_date);
}

// Both decoders run on every ROBOT_MESSAGE; one the fixture leaves out (or null) must say nullopt.
void CheckRobotMessage(Case& c) {
  const std::optional<RobotMessage> message = DecodeRobotMessage(c.package.body);
  if (const nlohmann::json* want = Member(c.expect, "robot_message")) {
    ASSERT_TRUE(message) << "DecodeRobotMessage gave nullopt";
    ExpectedFields fields(*want);
    ExpectRobotMessage(fields, *message);
    EXPECT_EQ(fields.Unchecked(), "");
    EXPECT_EQ(EncodeRobotMessage(*message), c.bytes) << "re-encoding gives other bytes";
  } else {
    EXPECT_FALSE(message) << "DecodeRobotMessage decoded a message the fixture says it skips";
  }
  const std::optional<VersionMessage> version = DecodeVersionMessage(c.package.body);
  if (const nlohmann::json* want = Member(c.expect, "version_message")) {
    ASSERT_TRUE(version) << "DecodeVersionMessage gave nullopt";
    ExpectedFields fields(*want);
    ExpectVersionMessage(fields, *version);
    EXPECT_EQ(fields.Unchecked(), "");
    BigEndianReader header(c.package.body.data(), c.package.body.size(), "fixture");
    EXPECT_EQ(EncodeVersionMessage(*version, header.U64()), c.bytes)
        << "re-encoding gives other bytes";
  } else {
    EXPECT_FALSE(version) << "DecodeVersionMessage decoded a message that is no VERSION";
  }
}

// version_message_python_urx_layout_no_build_field: python-urx reads one int32 after major/minor,
// we read two (as the UR client library's literal 5.24 capture has), so on this layout the first
// four date characters become `build` and the date loses them.
void ReadsBuildFromTheDate(Case& c) {
  EXPECT_FALSE(Member(c.expect, "robot_message"));
  EXPECT_FALSE(DecodeRobotMessage(c.package.body));
  const std::optional<VersionMessage> version = DecodeVersionMessage(c.package.body);
  ASSERT_TRUE(version);
  ExpectedFields want(c.expect["version_message"]);
  ExpectField(want, "project_name", version->project_name);
  ExpectField(want, "major", version->major);
  ExpectField(want, "minor", version->minor);
  ExpectField(want, "bugfix", version->bugfix);
  const std::string date = want["build_date"].get<std::string>();
  ASSERT_GE(date.size(), 4u);
  BigEndianReader date_start(reinterpret_cast<const uint8_t*>(date.data()), 4, "date");
  EXPECT_EQ(version->build, date_start.I32());
  EXPECT_EQ(version->build_date, date.substr(4));
  EXPECT_EQ(want.Unchecked(), "");
}

// --- ROBOT_STATE ------------------------------------------------------------------------------

void ExpectMode(ExpectedFields& want, const RobotModeData& got) {
  const RobotModeData d;
  ExpectFieldOr(want, "timestamp_us", got.timestamp_us, d.timestamp_us);
  ExpectFieldOr(want, "real_robot_connected", got.real_robot_connected, d.real_robot_connected);
  ExpectFieldOr(want, "real_robot_enabled", got.real_robot_enabled, d.real_robot_enabled);
  ExpectFieldOr(want, "power_on", got.power_on, d.power_on);
  ExpectFieldOr(want, "emergency_stopped", got.emergency_stopped, d.emergency_stopped);
  ExpectFieldOr(want, "protective_stopped", got.protective_stopped, d.protective_stopped);
  ExpectFieldOr(want, "program_running", got.program_running, d.program_running);
  ExpectFieldOr(want, "program_paused", got.program_paused, d.program_paused);
  ExpectFieldOr(want, "robot_mode", got.robot_mode, d.robot_mode);
  ExpectFieldOr(want, "control_mode", got.control_mode, d.control_mode);
  ExpectFieldOr(want, "target_speed_fraction", got.target_speed_fraction, d.target_speed_fraction);
  ExpectFieldOr(want, "speed_scaling", got.speed_scaling, d.speed_scaling);
  ExpectFieldOr(want, "target_speed_fraction_limit", got.target_speed_fraction_limit,
                d.target_speed_fraction_limit);
}

void ExpectJoints(ExpectedFields& want, const JointData& got) {
  const JointData d;
  ExpectFieldOr(want, "q_actual", got.q_actual, d.q_actual);
  ExpectFieldOr(want, "q_target", got.q_target, d.q_target);
  ExpectFieldOr(want, "qd_actual", got.qd_actual, d.qd_actual);
  ExpectFieldOr(want, "current", got.current, d.current);
  ExpectFieldOr(want, "voltage", got.voltage, d.voltage);
  ExpectFieldOr(want, "motor_temperature", got.motor_temperature, d.motor_temperature);
  ExpectFieldOr(want, "micro_temperature", got.micro_temperature, d.micro_temperature);
  ExpectFieldOr(want, "mode", got.mode, d.mode);
}

void ExpectCartesian(ExpectedFields& want, const CartesianInfo& got) {
  const CartesianInfo d;
  ExpectFieldOr(want, "pose", got.pose, d.pose);
  ExpectFieldOr(want, "tcp_offset", got.tcp_offset, d.tcp_offset);
}

void ExpectKinematics(ExpectedFields& want, const KinematicsInfo& got) {
  const KinematicsInfo d;
  ExpectFieldOr(want, "checksum", got.checksum, d.checksum);
  ExpectFieldOr(want, "theta", got.theta, d.theta);
  ExpectFieldOr(want, "a", got.a, d.a);
  ExpectFieldOr(want, "d", got.d, d.d);
  ExpectFieldOr(want, "alpha", got.alpha, d.alpha);
  ExpectFieldOr(want, "calibration_status", got.calibration_status, d.calibration_status);
}

// The sub-packages of a ROBOT_STATE body in order (they are framed like packages).
std::vector<Bytes> SubPackages(const Bytes& body) {
  PackageFramer framer;
  framer.Append(body.data(), body.size());
  std::vector<Bytes> subs;
  while (std::optional<Package> sub = framer.Next())
    subs.push_back(FramePackage(sub->type, sub->body));
  return subs;
}

// Our encoder writes the CB3 3.5 layouts. A sub-package of that size must re-encode to the same
// bytes; a shorter one (CB3 3.0-3.4 layouts, python-urx ursecmon) must be a prefix of ours, since
// newer software only appends fields.
template <class T>
void ExpectReencoded(const std::map<uint8_t, Bytes>& original, uint8_t type,
                     const RobotStateMessage& state, std::optional<T> RobotStateMessage::*member) {
  if (!(state.*member)) return;
  SCOPED_TRACE("re-encoding sub-package " + std::to_string(type));
  const auto found = original.find(type);
  ASSERT_NE(found, original.end());
  RobotStateMessage one;
  one.*member = state.*member;
  const Bytes framed = EncodeRobotState(one);
  const Bytes ours(framed.begin() + kHeaderSize, framed.end());
  const Bytes& theirs = found->second;
  if (theirs.size() == ours.size()) {
    EXPECT_EQ(ours, theirs);
    return;
  }
  ASSERT_LT(theirs.size(), ours.size()) << "a sub-package longer than our layout";
  EXPECT_EQ(theirs[4], ours[4]);
  EXPECT_TRUE(std::equal(theirs.begin() + kHeaderSize, theirs.end(), ours.begin() + kHeaderSize))
      << "an older layout that is not a prefix of ours";
}

template <class T, class Compare>
void CheckMember(ExpectedFields& expect, const std::string& key, const std::optional<T>& got,
                 Compare compare) {
  if (const nlohmann::json* want = Member(expect, key)) {
    ASSERT_TRUE(got) << key << " missing from the decoded state";
    ExpectedFields fields(*want);
    compare(fields, *got);
    EXPECT_EQ(fields.Unchecked(), "") << "in " << key;
  } else {
    EXPECT_FALSE(got) << key << " decoded although the fixture has none";
  }
}

void CheckRobotState(Case& c) {
  std::vector<uint8_t> types;
  std::map<uint8_t, Bytes> by_type;
  for (const Bytes& sub : SubPackages(c.package.body)) {
    types.push_back(sub[4]);
    by_type[sub[4]] = sub;
  }
  ExpectField(c.expect, "sub_package_types", types);

  const RobotStateMessage state = DecodeRobotState(c.package.body);
  CheckMember(c.expect, "mode", state.mode, ExpectMode);
  CheckMember(c.expect, "joints", state.joints, ExpectJoints);
  CheckMember(c.expect, "cartesian", state.cartesian, ExpectCartesian);
  CheckMember(c.expect, "kinematics", state.kinematics, ExpectKinematics);

  ExpectReencoded(by_type, kRobotModeDataType, state, &RobotStateMessage::mode);
  ExpectReencoded(by_type, kJointDataType, state, &RobotStateMessage::joints);
  ExpectReencoded(by_type, kCartesianInfoType, state, &RobotStateMessage::cartesian);
  ExpectReencoded(by_type, kKinematicsInfoType, state, &RobotStateMessage::kinematics);
}

// Frames the case's hex, checks the header against expect package_size/type, runs `check`.
testing::CaseCheck Framed(void (*check)(Case&)) {
  return [check](const nlohmann::json& json, ExpectedFields& expect) {
    Case c{expect, testing::ParseHex(json.at("hex").get<std::string>()), {}};
    c.package = FrameOnePackage(c.bytes);
    ExpectField(c.expect, "package_size", c.bytes.size());
    ExpectField(c.expect, "package_type", c.package.type);
    check(c);
  };
}

testing::CaseChecks Checks() {
  testing::CaseChecks checks;
  checks.by_packet = {
      {"ROBOT_MESSAGE (20) / VERSION (3)", Framed(CheckRobotMessage)},
      {"ROBOT_MESSAGE (20) / VERSION (3), layout without int32 build", Framed(CheckRobotMessage)},
      {"ROBOT_MESSAGE (20) / RUNTIME_EXCEPTION (10)", Framed(CheckRobotMessage)},
      {"ROBOT_MESSAGE (20) / KEY (7)", Framed(CheckRobotMessage)},
      {"ROBOT_MESSAGE (20) / TEXT (0)", Framed(CheckRobotMessage)},
      {"ROBOT_STATE (16) with 13 sub-packages", Framed(CheckRobotState)},
      {"ROBOT_STATE (16): ROBOT_MODE_DATA(47) JOINT_DATA(251) type 9(53) CARTESIAN_INFO(101) "
       "KINEMATICS_INFO(225) ADDITIONAL_INFO(7)",
       Framed(CheckRobotState)},
      {"ROBOT_STATE (16): ROBOT_MODE_DATA(46, no reserved byte) CARTESIAN_INFO(101)",
       Framed(CheckRobotState)},
      {"ROBOT_STATE (16): ROBOT_MODE_DATA(38, two doubles) CARTESIAN_INFO(53, pose only)",
       Framed(CheckRobotState)},
  };
  checks.disagreements = {
      {"version_message_python_urx_layout_no_build_field", Framed(ReadsBuildFromTheDate)}};
  return checks;
}

TEST(PrimaryFixtures, EveryCaseDecodesAndReencodesAsItsSourceSays) {
  const nlohmann::json file =
      testing::LoadFixtureFile("tests/drivers/robot/protocol/fixtures/primary.json");
  EXPECT_EQ(file["cases"].size(), kFixtureCases);
  EXPECT_EQ(testing::CheckFixtureCases(file, Checks()), file["cases"].size());
}

}  // namespace
}  // namespace avc::robot::primary
