// The LT360 grammar: reply parsing, command formatting and matching through the table, the
// JSON table loader and the CR/NUL frame splitter.

#include "drivers/turntable/protocol/lt360_protocol.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/test_support.h"

namespace avc::turntable {
namespace {

TEST(Lt360Protocol, ParsesPositionsInTenths) {
  EXPECT_EQ(ParsePositionTenths("+123.4"), 1234);
  EXPECT_EQ(ParsePositionTenths("-0.5"), -5);
  EXPECT_EQ(ParsePositionTenths("359.9"), 3599);
  EXPECT_EQ(ParsePositionTenths(" +0.0 "), 0);
  EXPECT_EQ(ParsePositionTenths("-180.0"), -1800);
}

TEST(Lt360Protocol, RejectsMalformedPositionsWithTheReplyQuoted) {
  for (const char* bad :
       {"", "+", "12", "12.", "12.34", "+1234.5", "1e2", "+12,3", "CW", "++1.0", "#~+\x7f?"}) {
    try {
      ParsePositionTenths(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const InvalidReply& e) {
      EXPECT_NE(std::string(e.what()).find("invalid position reply"), std::string::npos);
    }
  }
  try {
    ParsePositionTenths("#~\x7f");
  } catch (const InvalidReply& e) {
    EXPECT_NE(std::string(e.what()).find("'#~\\x7f'"), std::string::npos) << e.what();
  }
}

TEST(Lt360Protocol, FormatsPositionsRoundTrip) {
  for (const int tenths : {0, 5, -5, 1234, -1800, 3599}) {
    EXPECT_EQ(ParsePositionTenths(FormatPositionTenths(tenths)), tenths);
  }
  EXPECT_EQ(FormatPositionTenths(1234), "+123.4");
  EXPECT_EQ(FormatPositionTenths(-5), "-0.5");
}

TEST(Lt360Protocol, ParsesMotionCaseInsensitively) {
  EXPECT_EQ(ParseMotion("CW"), Motion::kCw);
  EXPECT_EQ(ParseMotion("ccw"), Motion::kCcw);
  EXPECT_EQ(ParseMotion("No"), Motion::kNone);
  EXPECT_THROW(ParseMotion("YES"), InvalidReply);
  EXPECT_THROW(ParseMotion("C W"), InvalidReply);
  EXPECT_THROW(ParseMotion(""), InvalidReply);
}

TEST(Lt360Protocol, FormatsCommandsFromTheTable) {
  CommandTable table;
  EXPECT_EQ(FormatCommand(table, CommandKind::kGetPosition), "CP");
  EXPECT_EQ(FormatCommand(table, CommandKind::kGotoShortest, 90), "GO 90.0");
  EXPECT_EQ(FormatCommand(table, CommandKind::kStep, -12.34), "STEP -12.3");
  EXPECT_EQ(FormatCommand(table, CommandKind::kStep, -0.01), "STEP 0.0");
  EXPECT_EQ(FormatCommand(table, CommandKind::kSetSpeed, 7.25), "SPEED 7.3");
  table.goto_cw = "";
  EXPECT_THROW(FormatCommand(table, CommandKind::kGotoCw, 1), ProtocolError);
  EXPECT_THROW(FormatCommand(table, CommandKind::kGotoShortest, std::nan("")), ProtocolError);
  table.goto_shortest = "LD {angle} DG NP GO";  // a Maturo-like template works the same way
  EXPECT_EQ(FormatCommand(table, CommandKind::kGotoShortest, 45), "LD 45.0 DG NP GO");
}

TEST(Lt360Protocol, MatchesCommandsCaseInsensitively) {
  CommandTable table;
  auto go = MatchCommand(table, "go 123.4");
  ASSERT_TRUE(go);
  EXPECT_EQ(go->kind, CommandKind::kGotoShortest);
  EXPECT_DOUBLE_EQ(*go->value, 123.4);
  auto cw = MatchCommand(table, " GoCw 10.0 ");
  ASSERT_TRUE(cw);
  EXPECT_EQ(cw->kind, CommandKind::kGotoCw);
  auto step = MatchCommand(table, "STEP -5.5");
  ASSERT_TRUE(step);
  EXPECT_EQ(step->kind, CommandKind::kStep);
  EXPECT_DOUBLE_EQ(*step->value, -5.5);
  auto cp = MatchCommand(table, "cp");
  ASSERT_TRUE(cp);
  EXPECT_EQ(cp->kind, CommandKind::kGetPosition);
  EXPECT_FALSE(cp->value);
  EXPECT_FALSE(MatchCommand(table, "GO"));
  EXPECT_FALSE(MatchCommand(table, "GO abc"));
  EXPECT_FALSE(MatchCommand(table, "CPX"));
  // Every formatted command matches back to its kind and value.
  for (const auto kind : {CommandKind::kGotoShortest, CommandKind::kGotoCw, CommandKind::kGotoCcw,
                          CommandKind::kStep, CommandKind::kSetSpeed}) {
    auto parsed = MatchCommand(table, FormatCommand(table, kind, 42.5));
    ASSERT_TRUE(parsed) << CommandKindName(kind);
    EXPECT_EQ(parsed->kind, kind);
    EXPECT_DOUBLE_EQ(*parsed->value, 42.5);
  }
}

TEST(Lt360Protocol, ValidatesTables) {
  CommandTable table;
  EXPECT_EQ(table.Validate(), "");
  table.get_position = "";
  EXPECT_NE(table.Validate().find("get_position"), std::string::npos);
  table = {};
  table.step = "STEP";
  EXPECT_NE(table.Validate().find("{angle}"), std::string::npos);
  table = {};
  table.home = "HOME {angle}";
  EXPECT_NE(table.Validate().find("home"), std::string::npos);
}

TEST(Lt360Protocol, LoadsTablesFromJson) {
  testing::TempDir dir("avc-lt360-table");
  testing::WriteFile(dir / "ok.json",
                     R"({"get_position": "PS?", "goto_cw": "", "done_reply": ""})");
  const CommandTable table = LoadCommandTable(dir / "ok.json");
  EXPECT_EQ(table.get_position, "PS?");
  EXPECT_FALSE(table.Supports(CommandKind::kGotoCw));
  EXPECT_EQ(table.get_moving, "MV");  // defaults kept
  EXPECT_EQ(table.done_reply, "");

  testing::WriteFile(dir / "unknown.json", R"({"goto": "G {angle}"})");
  try {
    LoadCommandTable(dir / "unknown.json");
    ADD_FAILURE() << "unknown key accepted";
  } catch (const ProtocolError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown key 'goto'"), std::string::npos) << e.what();
  }
  testing::WriteFile(dir / "bad.json", "{not json");
  EXPECT_THROW(LoadCommandTable(dir / "bad.json"), ProtocolError);
  testing::WriteFile(dir / "number.json", R"({"stop": 3})");
  EXPECT_THROW(LoadCommandTable(dir / "number.json"), ProtocolError);
  EXPECT_THROW(LoadCommandTable(dir / "missing.json"), ProtocolError);
}

// The shipped JSON is the starting point for transcribing the EX manual: it must stay equal to
// the built-in defaults.
TEST(Lt360Protocol, ShippedTableFileEqualsTheDefaults) {
  const CommandTable file = LoadCommandTable(testing::SourceDir() /
                                             "drivers/turntable/protocol/lt360_command_table.json");
  const CommandTable defaults;
  for (const auto kind :
       {CommandKind::kGetPosition, CommandKind::kGetMoving, CommandKind::kGotoShortest,
        CommandKind::kGotoCw, CommandKind::kGotoCcw, CommandKind::kStep, CommandKind::kHome,
        CommandKind::kStop, CommandKind::kSetSpeed}) {
    EXPECT_EQ(file.Template(kind), defaults.Template(kind)) << CommandKindName(kind);
  }
  EXPECT_EQ(file.done_reply, defaults.done_reply);
  EXPECT_EQ(file.error_reply, defaults.error_reply);
}

TEST(Lt360Protocol, SplitsFramesOnCrAndNul) {
  FrameSplitter splitter;
  splitter.Feed("+12");
  EXPECT_FALSE(splitter.Next());
  EXPECT_EQ(splitter.pending_bytes(), 3u);
  splitter.Feed(std::string_view(".3\r\nCW\0NO", 9));
  EXPECT_EQ(splitter.Next(), "+12.3");
  EXPECT_EQ(splitter.Next(), "CW");
  EXPECT_FALSE(splitter.Next());  // "NO" waits for its terminator
  splitter.Clear();
  EXPECT_EQ(splitter.pending_bytes(), 0u);
}

}  // namespace
}  // namespace avc::turntable
