#pragma once

// The LT360 RS-232 grammar: CR- (or NUL-) terminated ASCII commands, case-insensitive, replies
// such as "+123.4" (tenths of a degree) and "CW"/"CCW"/"NO". The exact command strings of the EX
// model are not documented publicly, so every string lives in a CommandTable
// that can be loaded from JSON once transcribed from the manual or a real transcript
// (drivers/turntable/protocol/lt360_command_table.json holds the defaults; pass an edited copy with
// `avc turntable --command-table`). The driver formats commands and parses replies here; the
// emulator matches commands here, so both speak whatever the table says.

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace avc::turntable {

class ProtocolError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A reply that does not have the expected form ("RS232 Invalid Return" in the LT360 manual).
class InvalidReply : public ProtocolError {
 public:
  using ProtocolError::ProtocolError;
};

enum class CommandKind {
  kGetPosition,
  kGetMoving,
  kGotoShortest,
  kGotoCw,
  kGotoCcw,
  kStep,
  kHome,
  kStop,
  kSetSpeed,
};
inline constexpr int kCommandKindCount = 9;

const char* CommandKindName(CommandKind kind);  // "goto_cw": also the JSON key

enum class Motion { kNone, kCw, kCcw };
const char* MotionName(Motion motion);  // "NO", "CW", "CCW"

// Command templates: "{angle}" (degrees, one decimal) or "{speed}" (deg/s, one decimal) marks
// the argument. An empty template means the device has no such command.
struct CommandTable {
  std::string get_position = "CP";
  std::string get_moving = "MV";
  std::string goto_shortest = "GO {angle}";
  std::string goto_cw = "GOCW {angle}";
  std::string goto_ccw = "GOCCW {angle}";
  std::string step = "STEP {angle}";
  std::string home = "HOME";
  std::string stop = "STOP";
  std::string set_speed = "SPEED {speed}";
  // What the device answers to an action (goto, step, home, stop, speed); empty = no answer.
  std::string done_reply = "OK";
  // What the device answers to a command it does not understand.
  std::string error_reply = "ERR";

  const std::string& Template(CommandKind kind) const;
  std::string& Template(CommandKind kind);
  bool Supports(CommandKind kind) const { return !Template(kind).empty(); }
  // Empty when valid; otherwise a sentence naming the bad entry.
  std::string Validate() const;
};

// Reads a JSON object whose keys are CommandKindName()s, "done_reply" and "error_reply"; keys
// left out keep the defaults above. Throws ProtocolError naming the file and the bad key.
CommandTable LoadCommandTable(const std::filesystem::path& path);

// The command line (without terminator) for kind with its argument. Throws ProtocolError when
// the table has no such command or the value is not finite.
std::string FormatCommand(const CommandTable& table, CommandKind kind, double value = 0);

struct ParsedCommand {
  CommandKind kind;
  std::optional<double> value;
};
// Which command a received line is (case-insensitive, surrounding spaces ignored); nullopt if
// none of the table's templates match.
std::optional<ParsedCommand> MatchCommand(const CommandTable& table, std::string_view line);

// "+123.4", "-0.5", "359.9" -> tenths of a degree. Strict: optional sign, 1-3 digits, a point
// and exactly one digit. Throws InvalidReply quoting the reply.
int ParsePositionTenths(std::string_view reply);
// "+123.4" for 1234 tenths.
std::string FormatPositionTenths(int tenths);
// "CW", "ccw", "No" -> Motion. Throws InvalidReply quoting the reply.
Motion ParseMotion(std::string_view reply);

// The device answers in either case: replies and commands compare case-insensitively.
bool EqualsIgnoreCase(std::string_view a, std::string_view b);

// Splits a byte stream into replies/commands terminated by CR or NUL; LF is dropped (some
// adapters add it). Bytes after the last terminator wait for more input.
class FrameSplitter {
 public:
  void Feed(std::string_view bytes);
  std::optional<std::string> Next();
  size_t pending_bytes() const { return pending_.size(); }
  void Clear();

 private:
  std::string pending_;
};

}  // namespace avc::turntable
