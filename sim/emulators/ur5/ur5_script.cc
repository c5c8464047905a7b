#include "sim/emulators/ur5/ur5_script.h"

#include <fmt/format.h>

#include <cctype>
#include <charconv>
#include <cmath>
#include <utility>
#include <variant>

#include "core/util/trim.h"

namespace avc::sim::ur5 {
namespace {

bool StartsBlock(const std::string& line) {
  return line.rfind("def ", 0) == 0 || line.rfind("sec ", 0) == 0;
}

std::optional<double> Number(const std::string& text) {
  const std::string trimmed(TrimSpace(text));
  double value = 0;
  const char* end = trimmed.data() + trimmed.size();
  const auto [ptr, ec] = std::from_chars(trimmed.data(), end, value);
  if (ec != std::errc() || ptr != end || trimmed.empty() || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

// Splits at commas outside brackets.
std::vector<std::string> SplitArguments(const std::string& text) {
  std::vector<std::string> parts;
  int depth = 0;
  std::string current;
  for (char c : text) {
    if (c == '[') ++depth;
    if (c == ']') --depth;
    if (c == ',' && depth == 0) {
      parts.push_back(std::string(TrimSpace(current)));
      current.clear();
    } else {
      current += c;
    }
  }
  if (!TrimSpace(current).empty() || !parts.empty())
    parts.push_back(std::string(TrimSpace(current)));
  return parts;
}

// "[a, b, ...]" or "p[a, b, ...]" with six numbers.
std::optional<std::array<double, 6>> Vector6(const std::string& text, bool& is_pose) {
  std::string body = std::string(TrimSpace(text));
  is_pose = !body.empty() && body[0] == 'p';
  if (is_pose) body = std::string(TrimSpace(body.substr(1)));
  if (body.size() < 2 || body.front() != '[' || body.back() != ']') return std::nullopt;
  const auto entries = SplitArguments(body.substr(1, body.size() - 2));
  if (entries.size() != 6) return std::nullopt;
  std::array<double, 6> values{};
  for (size_t i = 0; i < 6; ++i) {
    const auto value = Number(entries[i]);
    if (!value) return std::nullopt;
    values[i] = *value;
  }
  return values;
}

// One statement line -> a statement, or an error text.
std::variant<ScriptStatement, std::string> ParseStatement(const std::string& line) {
  const size_t open = line.find('(');
  if (open == std::string::npos || line.back() != ')') {
    return fmt::format("unsupported statement '{}'", line);
  }
  const std::string name(TrimSpace(line.substr(0, open)));
  const auto arguments = SplitArguments(line.substr(open + 1, line.size() - open - 2));
  ScriptStatement statement;
  if (name == "movej") {
    statement.kind = ScriptStatement::Kind::kMoveJ;
    statement.acceleration = 1.4;
    statement.velocity = 1.05;
  } else if (name == "movel") {
    statement.kind = ScriptStatement::Kind::kMoveL;
    statement.acceleration = 1.2;
    statement.velocity = 0.25;
  } else if (name == "stopj") {
    statement.kind = ScriptStatement::Kind::kStopJ;
    if (arguments.size() != 1) return std::string("stopj expects one argument (deceleration)");
    const auto deceleration = Number(arguments[0]);
    if (!deceleration || *deceleration <= 0) return "stopj: bad deceleration " + arguments[0];
    statement.acceleration = *deceleration;
    return statement;
  } else {
    return fmt::format("unsupported function '{}' (the emulator runs movej, movel, stopj)", name);
  }
  if (arguments.empty()) return name + ": missing target";
  const auto target = Vector6(arguments[0], statement.target_is_pose);
  if (!target) return fmt::format("{}: target '{}' is not a list of 6 numbers", name, arguments[0]);
  statement.target = *target;
  if (statement.kind == ScriptStatement::Kind::kMoveL && !statement.target_is_pose) {
    return std::string("movel: target must be a pose p[...]");
  }
  // Positional order after the target: a, v, t, r.
  static constexpr std::array<const char*, 4> kNames = {"a", "v", "t", "r"};
  for (size_t i = 1; i < arguments.size(); ++i) {
    std::string key = i - 1 < kNames.size() ? kNames[i - 1] : "";
    std::string value_text = arguments[i];
    if (const size_t eq = arguments[i].find('='); eq != std::string::npos) {
      key = std::string(TrimSpace(arguments[i].substr(0, eq)));
      value_text = arguments[i].substr(eq + 1);
    }
    const auto value = Number(value_text);
    if (!value) return fmt::format("{}: argument '{}' is not a number", name, arguments[i]);
    if (key == "a") {
      statement.acceleration = *value;
    } else if (key == "v") {
      statement.velocity = *value;
    } else if ((key == "t" || key == "r") && *value == 0) {
      // time and blend radius 0 are the defaults; anything else is not emulated
    } else {
      return fmt::format("{}: argument '{}' is not supported", name, arguments[i]);
    }
  }
  if (!(statement.acceleration > 0 && statement.velocity > 0)) {
    return fmt::format("{}: a and v must be positive", name);
  }
  return statement;
}

}  // namespace

ScriptProgram ParseScriptUnit(const std::vector<std::string>& lines) {
  ScriptProgram program;
  if (lines.empty()) return program;
  size_t first = 0, last = lines.size();
  if (StartsBlock(lines.front())) {
    const std::string header(TrimSpace(lines.front().substr(4)));
    const size_t paren = header.find('(');
    if (paren == std::string::npos || header.back() != ':') {
      program.error = ScriptError{1, 1, fmt::format("malformed program header '{}'", lines[0])};
      return program;
    }
    program.name = std::string(TrimSpace(header.substr(0, paren)));
    first = 1;
    last = lines.size() - 1;  // the column-0 "end"
  }
  for (size_t i = first; i < last; ++i) {
    const std::string line(TrimSpace(lines[i]));
    if (line.empty() || line[0] == '#') continue;
    const int line_number = static_cast<int>(i) + 1;
    auto parsed = ParseStatement(line);
    if (auto* error = std::get_if<std::string>(&parsed)) {
      const int column = static_cast<int>(lines[i].find_first_not_of(" \t")) + 1;
      program.error = ScriptError{line_number, column, *error};
      program.statements.clear();
      return program;
    }
    auto statement = std::get<ScriptStatement>(parsed);
    statement.line = line_number;
    program.statements.push_back(statement);
  }
  return program;
}

void ScriptAssembler::Append(const std::string& text) { pending_ += text; }

std::optional<std::vector<std::string>> ScriptAssembler::Next() {
  while (true) {
    const size_t end = pending_.find('\n');
    if (end == std::string::npos) return std::nullopt;
    std::string line = pending_.substr(0, end);
    pending_.erase(0, end + 1);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (in_block_) {
      block_.push_back(line);
      if (TrimSpace(line) == "end" && !line.empty() && line[0] == 'e') {
        in_block_ = false;
        return std::exchange(block_, {});
      }
      continue;
    }
    if (StartsBlock(line)) {
      in_block_ = true;
      block_ = {line};
      continue;
    }
    if (!TrimSpace(line).empty()) return std::vector<std::string>{line};
  }
}

}  // namespace avc::sim::ur5
