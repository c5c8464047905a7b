#include <toml++/toml.h>

#include <algorithm>

#include "core/launch/config_tree.h"
#include "core/launch/launch_file_error.h"

namespace avc::launch {
namespace {

int LineOf(const toml::source_region& source) { return static_cast<int>(source.begin.line); }

ConfigValue Convert(const toml::node& node) {
  ConfigValue value;
  value.line = LineOf(node.source());
  if (const auto* text = node.as_string()) {
    value.kind = ConfigValue::Kind::kString;
    value.text = text->get();
  } else if (const auto* integer = node.as_integer()) {
    value.kind = ConfigValue::Kind::kNumber;
    value.number = static_cast<double>(integer->get());
  } else if (const auto* floating = node.as_floating_point()) {
    value.kind = ConfigValue::Kind::kNumber;
    value.number = floating->get();
  } else if (node.is_boolean()) {
    value.kind = ConfigValue::Kind::kBool;
  } else if (const auto* array = node.as_array()) {
    value.kind = ConfigValue::Kind::kArray;
    for (const toml::node& item : *array) value.items.push_back(Convert(item));
  } else if (const auto* table = node.as_table()) {
    value.kind = ConfigValue::Kind::kTable;
    for (const auto& [key, child] : *table) {
      value.entries.push_back(
          ConfigEntry{std::string(key.str()), LineOf(key.source()), Convert(child)});
    }
    // toml++ keeps keys sorted by name; the schema check reports in file order.
    std::stable_sort(value.entries.begin(), value.entries.end(),
                     [](const ConfigEntry& a, const ConfigEntry& b) { return a.line < b.line; });
  } else {
    value.kind = ConfigValue::Kind::kOther;  // dates and times
  }
  return value;
}

}  // namespace

ConfigValue ReadTomlTree(std::string_view text, const std::string& file) {
  try {
    const toml::table table = toml::parse(text, std::string_view(file));
    ConfigValue root = Convert(table);
    root.line = 1;
    return root;
  } catch (const toml::parse_error& e) {
    throw LaunchFileError(file, LineOf(e.source()), std::string(e.description()));
  }
}

}  // namespace avc::launch
