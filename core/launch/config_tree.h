#pragma once

// A format-neutral document tree with line numbers, so TOML and YAML launch files go through one
// schema check and give the same errors.

#include <string>
#include <string_view>
#include <vector>

namespace avc::launch {

struct ConfigEntry;

struct ConfigValue {
  enum class Kind { kNull, kString, kNumber, kBool, kArray, kTable, kOther };
  Kind kind = Kind::kNull;
  int line = 0;
  std::string text;  // kString
  // A YAML plain scalar: untyped text that may also be read as a number.
  bool plain = false;
  double number = 0;                 // kNumber
  std::vector<ConfigValue> items;    // kArray
  std::vector<ConfigEntry> entries;  // kTable, in file order
};

struct ConfigEntry {
  std::string key;
  int line = 0;
  ConfigValue value;
};

// "a string", "an array", ... for error messages.
const char* KindName(ConfigValue::Kind kind);

// Parse text into a tree; syntax errors throw LaunchFileError naming file and line.
ConfigValue ReadTomlTree(std::string_view text, const std::string& file);
ConfigValue ReadYamlTree(std::string_view text, const std::string& file);

}  // namespace avc::launch
