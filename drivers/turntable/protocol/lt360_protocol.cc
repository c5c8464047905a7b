#include "drivers/turntable/protocol/lt360_protocol.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/util/trim.h"

namespace avc::turntable {
namespace {

constexpr std::array<CommandKind, kCommandKindCount> kAllKinds = {
    CommandKind::kGetPosition, CommandKind::kGetMoving, CommandKind::kGotoShortest,
    CommandKind::kGotoCw,      CommandKind::kGotoCcw,   CommandKind::kStep,
    CommandKind::kHome,        CommandKind::kStop,      CommandKind::kSetSpeed};

// The argument field ("{angle}", "{speed}") a command of this kind must carry; empty for
// commands without argument.
std::string_view ArgumentField(CommandKind kind) {
  switch (kind) {
    case CommandKind::kGotoShortest:
    case CommandKind::kGotoCw:
    case CommandKind::kGotoCcw:
    case CommandKind::kStep:
      return "{angle}";
    case CommandKind::kSetSpeed:
      return "{speed}";
    default:
      return "";
  }
}

// Replies are quoted with control characters escaped, so a garbled reply is readable.
std::string Quote(std::string_view text) {
  std::string out = "'";
  for (const char c : text) {
    if (std::isprint(static_cast<unsigned char>(c))) {
      out += c;
    } else {
      out += fmt::format("\\x{:02x}", static_cast<unsigned char>(c));
    }
  }
  return out + "'";
}

// A number with an optional sign, digits and an optional fraction; nullopt otherwise.
std::optional<double> ParseNumber(std::string_view text) {
  text = TrimSpace(text);
  if (text.empty()) return std::nullopt;
  std::string_view digits = text;
  if (digits.front() == '+') digits.remove_prefix(1);
  double value = 0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (error != std::errc() || end != digits.data() + digits.size() || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

}  // namespace

bool EqualsIgnoreCase(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (std::toupper(static_cast<unsigned char>(a[i])) !=
        std::toupper(static_cast<unsigned char>(b[i]))) {
      return false;
    }
  }
  return true;
}

const char* CommandKindName(CommandKind kind) {
  switch (kind) {
    case CommandKind::kGetPosition:
      return "get_position";
    case CommandKind::kGetMoving:
      return "get_moving";
    case CommandKind::kGotoShortest:
      return "goto_shortest";
    case CommandKind::kGotoCw:
      return "goto_cw";
    case CommandKind::kGotoCcw:
      return "goto_ccw";
    case CommandKind::kStep:
      return "step";
    case CommandKind::kHome:
      return "home";
    case CommandKind::kStop:
      return "stop";
    case CommandKind::kSetSpeed:
      return "set_speed";
  }
  return "unknown";
}

const char* MotionName(Motion motion) {
  switch (motion) {
    case Motion::kNone:
      return "NO";
    case Motion::kCw:
      return "CW";
    case Motion::kCcw:
      return "CCW";
  }
  return "?";
}

const std::string& CommandTable::Template(CommandKind kind) const {
  return const_cast<CommandTable*>(this)->Template(kind);
}

std::string& CommandTable::Template(CommandKind kind) {
  switch (kind) {
    case CommandKind::kGetPosition:
      return get_position;
    case CommandKind::kGetMoving:
      return get_moving;
    case CommandKind::kGotoShortest:
      return goto_shortest;
    case CommandKind::kGotoCw:
      return goto_cw;
    case CommandKind::kGotoCcw:
      return goto_ccw;
    case CommandKind::kStep:
      return step;
    case CommandKind::kHome:
      return home;
    case CommandKind::kStop:
      return stop;
    case CommandKind::kSetSpeed:
      return set_speed;
  }
  throw ProtocolError("unknown command kind");
}

std::string CommandTable::Validate() const {
  for (const CommandKind kind : {CommandKind::kGetPosition, CommandKind::kGetMoving,
                                 CommandKind::kGotoShortest, CommandKind::kStop}) {
    if (!Supports(kind)) {
      return fmt::format("command table: '{}' is required but empty", CommandKindName(kind));
    }
  }
  for (const CommandKind kind : kAllKinds) {
    const std::string& text = Template(kind);
    if (text.empty()) continue;
    const std::string_view argument_field = ArgumentField(kind);
    const size_t braces = std::count(text.begin(), text.end(), '{');
    if (argument_field.empty() ? braces != 0
                               : (braces != 1 || text.find(argument_field) == std::string::npos)) {
      return fmt::format("command table: '{}' = {} must contain {}", CommandKindName(kind),
                         Quote(text),
                         argument_field.empty() ? std::string("no argument field")
                                                : "exactly one " + std::string(argument_field));
    }
    if (text.find_first_of(std::string("\r\n\0", 3)) != std::string::npos) {
      return fmt::format("command table: '{}' contains a terminator", CommandKindName(kind));
    }
  }
  return "";
}

CommandTable LoadCommandTable(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw ProtocolError("cannot read command table " + path.string());
  nlohmann::json json;
  try {
    json = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw ProtocolError(fmt::format("command table {}: not JSON: {}", path.string(), e.what()));
  }
  if (!json.is_object()) {
    throw ProtocolError("command table " + path.string() + ": expected a JSON object");
  }
  CommandTable table;
  for (const auto& [key, value] : json.items()) {
    std::string* field = nullptr;
    for (const CommandKind kind : kAllKinds) {
      if (key == CommandKindName(kind)) field = &table.Template(kind);
    }
    if (key == "done_reply") field = &table.done_reply;
    if (key == "error_reply") field = &table.error_reply;
    if (field == nullptr) {
      throw ProtocolError(fmt::format("command table {}: unknown key '{}'", path.string(), key));
    }
    if (!value.is_string()) {
      throw ProtocolError(
          fmt::format("command table {}: '{}' must be a string", path.string(), key));
    }
    *field = value.get<std::string>();
  }
  const std::string problem = table.Validate();
  if (!problem.empty()) throw ProtocolError(path.string() + ": " + problem);
  return table;
}

std::string FormatCommand(const CommandTable& table, CommandKind kind, double value) {
  const std::string& text = table.Template(kind);
  if (text.empty()) {
    throw ProtocolError(
        fmt::format("the command table has no '{}' command", CommandKindName(kind)));
  }
  const std::string_view argument_field = ArgumentField(kind);
  if (argument_field.empty()) return text;
  if (!std::isfinite(value)) {
    throw ProtocolError(
        fmt::format("'{}' needs a finite value, got {}", CommandKindName(kind), value));
  }
  std::string out = text;
  // Values are sent in the device's 0.1 unit; "-0.0" is never sent.
  const double rounded = std::round(value * 10) / 10;
  out.replace(out.find(argument_field), argument_field.size(),
              fmt::format("{:.1f}", rounded == 0 ? 0.0 : rounded));
  return out;
}

std::optional<ParsedCommand> MatchCommand(const CommandTable& table, std::string_view line) {
  line = TrimSpace(line);
  for (const CommandKind kind : kAllKinds) {
    const std::string& text = table.Template(kind);
    if (text.empty()) continue;
    const std::string_view argument_field = ArgumentField(kind);
    if (argument_field.empty()) {
      if (EqualsIgnoreCase(line, text)) return ParsedCommand{kind, std::nullopt};
      continue;
    }
    const size_t at = text.find(argument_field);
    const std::string_view prefix = std::string_view(text).substr(0, at);
    const std::string_view suffix = std::string_view(text).substr(at + argument_field.size());
    if (line.size() <= prefix.size() + suffix.size()) continue;
    if (!EqualsIgnoreCase(line.substr(0, prefix.size()), prefix) ||
        !EqualsIgnoreCase(line.substr(line.size() - suffix.size()), suffix)) {
      continue;
    }
    const std::optional<double> value =
        ParseNumber(line.substr(prefix.size(), line.size() - prefix.size() - suffix.size()));
    if (value) return ParsedCommand{kind, value};
  }
  return std::nullopt;
}

int ParsePositionTenths(std::string_view reply) {
  const std::string_view text = TrimSpace(reply);
  size_t i = 0;
  bool negative = false;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) negative = text[i++] == '-';
  int whole = 0;
  int digits = 0;
  while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])) && digits < 4) {
    whole = whole * 10 + (text[i++] - '0');
    ++digits;
  }
  const bool valid = digits >= 1 && digits <= 3 && i + 2 == text.size() && text[i] == '.' &&
                     std::isdigit(static_cast<unsigned char>(text[i + 1]));
  if (!valid) {
    throw InvalidReply(
        fmt::format("invalid position reply {} (expected a signed angle in tenths "
                    "of a degree such as '+123.4')",
                    Quote(reply)));
  }
  const int tenths = whole * 10 + (text[i + 1] - '0');
  return negative ? -tenths : tenths;
}

std::string FormatPositionTenths(int tenths) {
  const int magnitude = std::abs(tenths);
  return fmt::format("{}{}.{}", tenths < 0 ? '-' : '+', magnitude / 10, magnitude % 10);
}

Motion ParseMotion(std::string_view reply) {
  const std::string_view text = TrimSpace(reply);
  if (EqualsIgnoreCase(text, "NO")) return Motion::kNone;
  if (EqualsIgnoreCase(text, "CW")) return Motion::kCw;
  if (EqualsIgnoreCase(text, "CCW")) return Motion::kCcw;
  throw InvalidReply(fmt::format("invalid moving reply {} (expected CW, CCW or NO)", Quote(reply)));
}

void FrameSplitter::Feed(std::string_view bytes) {
  for (const char c : bytes) {
    if (c != '\n') pending_ += c;
  }
}

std::optional<std::string> FrameSplitter::Next() {
  const size_t end = pending_.find_first_of(std::string("\r\0", 2));
  if (end == std::string::npos) return std::nullopt;
  std::string frame = pending_.substr(0, end);
  pending_.erase(0, end + 1);
  return frame;
}

void FrameSplitter::Clear() { pending_.clear(); }

}  // namespace avc::turntable
