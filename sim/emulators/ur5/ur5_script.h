#pragma once

// The URScript subset the emulator runs: `def name():` ... `end` programs (and one-line
// statements) made of movej, movel and stopj calls. Anything else is an error the controller
// reports as a runtime exception, so a driver sending unsupported script notices.

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace avc::sim::ur5 {

struct ScriptStatement {
  enum class Kind { kMoveJ, kMoveL, kStopJ };
  Kind kind = Kind::kMoveJ;
  std::array<double, 6> target{};  // joints, or a pose when `target_is_pose`
  bool target_is_pose = false;
  double acceleration = 1.4;
  double velocity = 1.05;
  int line = 0;
};

struct ScriptError {
  int line = 0;
  int column = 0;
  std::string text;
};

struct ScriptProgram {
  std::string name;  // empty for a one-line statement
  std::vector<ScriptStatement> statements;
  std::optional<ScriptError> error;
};

// Parses one unit: a def/sec block's lines (first "def name():", last "end") or a single
// statement line. Never throws: problems come back in `error`.
ScriptProgram ParseScriptUnit(const std::vector<std::string>& lines);

// Splits the byte stream received on 30002 into units: a def/sec block once its column-0 `end`
// arrived, or one non-empty line outside a block.
class ScriptAssembler {
 public:
  void Append(const std::string& text);
  std::optional<std::vector<std::string>> Next();

 private:
  std::string pending_;
  std::vector<std::string> block_;
  bool in_block_ = false;
};

}  // namespace avc::sim::ur5
