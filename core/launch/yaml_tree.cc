#include <yaml-cpp/yaml.h>

#include <map>

#include "core/launch/config_tree.h"
#include "core/launch/launch_file_error.h"

namespace avc::launch {
namespace {

// yaml-cpp counts lines from 0.
int LineOf(const YAML::Node& node, int fallback) {
  const int line = node.Mark().line;
  return line >= 0 ? line + 1 : fallback;
}

ConfigValue Convert(const YAML::Node& node, const std::string& file, int fallback_line) {
  ConfigValue value;
  value.line = LineOf(node, fallback_line);
  switch (node.Type()) {
    case YAML::NodeType::Scalar:
      value.kind = ConfigValue::Kind::kString;
      value.text = node.Scalar();
      value.plain = node.Tag() == "?";
      break;
    case YAML::NodeType::Sequence:
      value.kind = ConfigValue::Kind::kArray;
      for (const YAML::Node& item : node) value.items.push_back(Convert(item, file, value.line));
      break;
    case YAML::NodeType::Map: {
      value.kind = ConfigValue::Kind::kTable;
      std::map<std::string, int> seen;
      for (const auto& pair : node) {
        const int key_line = LineOf(pair.first, value.line);
        if (!pair.first.IsScalar())
          throw LaunchFileError(file, key_line, "keys must be plain names");
        const std::string key = pair.first.Scalar();
        // yaml-cpp accepts repeated keys silently; a repeated key is almost always a mistake.
        if (auto [it, inserted] = seen.emplace(key, key_line); !inserted) {
          throw LaunchFileError(
              file, key_line,
              "duplicate key '" + key + "' (first on line " + std::to_string(it->second) + ")");
        }
        value.entries.push_back(ConfigEntry{key, key_line, Convert(pair.second, file, key_line)});
      }
      break;
    }
    default:
      value.kind = ConfigValue::Kind::kNull;
      // An empty value ("command:") has no text of its own: yaml-cpp marks it where the next
      // token starts, often a later line. Its key's line is the one to report.
      value.line = fallback_line;
  }
  return value;
}

}  // namespace

ConfigValue ReadYamlTree(std::string_view text, const std::string& file) {
  YAML::Node document;
  try {
    document = YAML::Load(std::string(text));
  } catch (const YAML::Exception& e) {
    throw LaunchFileError(file, e.mark.line >= 0 ? e.mark.line + 1 : 0, e.msg);
  }
  if (document.IsNull()) {
    ConfigValue empty;
    empty.kind = ConfigValue::Kind::kTable;
    empty.line = 1;
    return empty;
  }
  return Convert(document, file, 1);
}

}  // namespace avc::launch
