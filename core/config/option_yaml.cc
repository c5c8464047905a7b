#include "core/config/option_yaml.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

namespace avc::config {
namespace {

std::string Where(const std::string& file, const YAML::Mark& mark) {
  return fmt::format("{}:{}", file, mark.line + 1);
}

void Flatten(const YAML::Node& map, const std::string& prefix, const std::string& file,
             std::vector<Assignment>* out) {
  for (const auto& entry : map) {
    const std::string name = prefix + entry.first.Scalar();
    const std::string where = Where(file, entry.first.Mark());
    const YAML::Node& value = entry.second;
    if (value.IsMap()) {
      Flatten(value, name + ".", file, out);
    } else if (value.IsScalar()) {
      out->push_back({name, value.Scalar(), where});
    } else {
      throw ConfigError(fmt::format("{}: {}: an option is a string, number or boolean, not {}",
                                    where, name, value.IsSequence() ? "a list" : "empty"));
    }
  }
}

}  // namespace

std::vector<Assignment> ReadYamlAssignments(std::string_view text, const std::string& file) {
  YAML::Node document;
  try {
    document = YAML::Load(std::string(text));
  } catch (const YAML::Exception& e) {
    throw ConfigError(fmt::format("{}: {}", Where(file, e.mark), e.msg));
  }
  std::vector<Assignment> assignments;
  if (document.IsNull()) return assignments;
  if (!document.IsMap()) {
    throw ConfigError(fmt::format("{}: a config file is a map of sections and options", file));
  }
  Flatten(document, "", file, &assignments);
  return assignments;
}

}  // namespace avc::config
