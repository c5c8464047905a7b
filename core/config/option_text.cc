#include "core/config/option_text.h"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/config/option_yaml.h"

namespace avc::config {
namespace {

std::string RangeProblem(double value, const OptionSpec& spec) {
  if (value < spec.min) return fmt::format("{} is below the minimum {}", value, spec.min);
  if (value > spec.max) return fmt::format("{} is above the maximum {}", value, spec.max);
  return "";
}

std::string Where(const std::string& file, const toml::source_region& source) {
  return fmt::format("{}:{}", file, source.begin.line);
}

// A TOML value's text as an option value, or throws naming the key.
std::string ValueText(const toml::node& node, const std::string& name, const std::string& where) {
  if (const auto* text = node.as_string()) return text->get();
  if (const auto* integer = node.as_integer()) return std::to_string(integer->get());
  if (const auto* real = node.as_floating_point()) return RealText(real->get());
  if (const auto* flag = node.as_boolean()) return flag->get() ? "true" : "false";
  throw ConfigError(fmt::format("{}: {}: an option is a string, number or boolean, not {}", where,
                                name, node.is_array() ? "an array" : "a date or time"));
}

struct LinedAssignment {
  int64_t line = 0;
  Assignment assignment;
};

void Flatten(const toml::table& table, const std::string& prefix, const std::string& file,
             std::vector<LinedAssignment>* out) {
  for (const auto& [key, node] : table) {
    const std::string name = prefix + std::string(key.str());
    const std::string where = Where(file, key.source());
    if (const auto* inner = node.as_table()) {
      Flatten(*inner, name + ".", file, out);
    } else {
      out->push_back({static_cast<int64_t>(key.source().begin.line),
                      {name, ValueText(node, name, where), where}});
    }
  }
}

std::string Quoted(const std::string& text) {
  std::ostringstream out;
  out << toml::value<std::string>(text);
  return out.str();
}

}  // namespace

Assignment ParseAssignment(std::string_view text, std::string where) {
  const size_t equals = text.find('=');
  if (equals == std::string_view::npos || equals == 0) {
    throw ConfigError(
        fmt::format("{} '{}': expected SECTION.FIELD=VALUE", where, std::string(text)));
  }
  return {std::string(text.substr(0, equals)), std::string(text.substr(equals + 1)),
          std::move(where)};
}

std::vector<Assignment> ReadTomlAssignments(std::string_view text, const std::string& file) {
  toml::table table;
  try {
    table = toml::parse(text, std::string_view(file));
  } catch (const toml::parse_error& e) {
    throw ConfigError(fmt::format("{}: {}", Where(file, e.source()), e.description()));
  }
  std::vector<LinedAssignment> lined;
  Flatten(table, "", file, &lined);
  // toml++ keeps keys sorted by name; errors read better in the file's order.
  std::stable_sort(
      lined.begin(), lined.end(),
      [](const LinedAssignment& a, const LinedAssignment& b) { return a.line < b.line; });
  std::vector<Assignment> assignments;
  for (LinedAssignment& item : lined) assignments.push_back(std::move(item.assignment));
  return assignments;
}

std::vector<Assignment> ReadConfigFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError(fmt::format("config file {} cannot be read", path));
  std::ostringstream text;
  text << in.rdbuf();
  const std::string extension = std::filesystem::path(path).extension().string();
  if (extension == ".yaml" || extension == ".yml") return ReadYamlAssignments(text.str(), path);
  return ReadTomlAssignments(text.str(), path);
}

std::vector<Assignment> ReadAssignments(const std::vector<std::string>& files,
                                        const std::vector<std::string>& sets) {
  std::vector<Assignment> assignments;
  for (const std::string& file : files) {
    for (Assignment& assignment : ReadConfigFile(file))
      assignments.push_back(std::move(assignment));
  }
  for (const std::string& text : sets) assignments.push_back(ParseAssignment(text, "--set"));
  return assignments;
}

int64_t ParseInteger(std::string_view text, const OptionSpec& spec) {
  int64_t value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (error != std::errc() || stop != end || text.empty()) {
    throw ConfigError(fmt::format("'{}' is not an integer", std::string(text)));
  }
  if (const std::string problem = RangeProblem(static_cast<double>(value), spec);
      !problem.empty()) {
    throw ConfigError(problem);
  }
  return value;
}

double ParseReal(std::string_view text, const OptionSpec& spec) {
  double value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (error != std::errc() || stop != end || text.empty() || !std::isfinite(value)) {
    throw ConfigError(fmt::format("'{}' is not a finite number", std::string(text)));
  }
  if (const std::string problem = RangeProblem(value, spec); !problem.empty()) {
    throw ConfigError(problem);
  }
  return value;
}

bool IsTomlLiteral(std::string_view text) {
  if (text == "true" || text == "false") return true;
  double value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  return !text.empty() && error == std::errc() && stop == end && std::isfinite(value) &&
         text.front() != '.' && text.back() != '.';
}

bool ParseSwitch(std::string_view text) {
  if (text == "true") return true;
  if (text == "false") return false;
  throw ConfigError(fmt::format("'{}' is not true or false", std::string(text)));
}

std::string RealText(double value) {
  std::string text = fmt::format("{}", value);
  if (std::isfinite(value) && text.find_first_of(".e") == std::string::npos) text += ".0";
  return text;
}

std::string RenderToml(const std::vector<NamedValue>& values) {
  const auto section_of = [](const std::string& name) {
    const size_t dot = name.rfind('.');
    return dot == std::string::npos ? std::string() : name.substr(0, dot);
  };
  std::vector<std::string> sections = {""};
  for (const NamedValue& value : values) {
    const std::string section = section_of(value.name);
    if (std::find(sections.begin(), sections.end(), section) == sections.end()) {
      sections.push_back(section);
    }
  }
  std::string text;
  for (const std::string& section : sections) {
    std::string lines;
    for (const NamedValue& value : values) {
      if (section_of(value.name) != section) continue;
      const std::string key = section.empty() ? value.name : value.name.substr(section.size() + 1);
      lines += fmt::format("{} = {}\n", key, value.quoted ? Quoted(value.text) : value.text);
    }
    if (lines.empty()) continue;
    if (!section.empty()) text += fmt::format("{}[{}]\n", text.empty() ? "" : "\n", section);
    text += lines;
  }
  return text;
}

}  // namespace avc::config
