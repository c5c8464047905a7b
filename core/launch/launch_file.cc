#include "core/launch/launch_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>

#include "core/launch/config_tree.h"
#include "core/launch/find_program.h"

namespace avc::launch {
namespace {

namespace fs = std::filesystem;
using Kind = ConfigValue::Kind;

constexpr std::array kTopLevelKeys = {"log_dir", "env", "process"};
constexpr std::array kProcessKeys = {"name", "command", "args",         "host",
                                     "env",  "restart", "stop_timeout", "working_dir"};

std::string Lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

size_t EditDistance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// Checks values against the schema; every error names the file and the line.
class SchemaReader {
 public:
  explicit SchemaReader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void Fail(int line, const std::string& problem) const {
    throw LaunchFileError(file_, line, problem);
  }

  template <size_t N>
  void CheckKeys(const ConfigValue& table, const std::array<const char*, N>& allowed,
                 const std::string& where) const {
    for (const ConfigEntry& entry : table.entries) {
      if (std::find_if(allowed.begin(), allowed.end(),
                       [&](const char* key) { return entry.key == key; }) != allowed.end()) {
        continue;
      }
      std::string hint;
      for (const char* key : allowed) {
        if (EditDistance(Lower(entry.key), key) <= 2) {
          hint = fmt::format(" (did you mean '{}'?)", key);
          break;
        }
      }
      std::string expected;
      for (const char* key : allowed) expected += (expected.empty() ? "" : ", ") + std::string(key);
      Fail(entry.line, fmt::format("unknown key '{}' in {}{}; allowed keys: {}", entry.key, where,
                                   hint, expected));
    }
  }

  std::string String(const ConfigEntry& entry, const std::string& what) const {
    if (entry.value.kind != Kind::kString) {
      Fail(LineOf(entry),
           fmt::format("{} must be a string, not {}", what, KindName(entry.value.kind)));
    }
    return entry.value.text;
  }

  std::string NonEmptyString(const ConfigEntry& entry, const std::string& what) const {
    std::string text = String(entry, what);
    if (text.empty()) Fail(LineOf(entry), what + " must not be empty");
    return text;
  }

  double Number(const ConfigEntry& entry, const std::string& what) const {
    const ConfigValue& value = entry.value;
    if (value.kind == Kind::kNumber) return value.number;
    if (value.kind == Kind::kString && value.plain) {
      double number = 0;
      const char* end = value.text.data() + value.text.size();
      auto [ptr, error] = std::from_chars(value.text.data(), end, number);
      if (error == std::errc() && ptr == end) return number;
    }
    Fail(LineOf(entry),
         fmt::format("{} must be a number, not {}", what,
                     value.kind == Kind::kString ? "'" + value.text + "'"
                                                 : std::string(KindName(value.kind))));
  }

  std::vector<std::string> StringList(const ConfigEntry& entry, const std::string& what) const {
    if (entry.value.kind != Kind::kArray) {
      Fail(LineOf(entry),
           fmt::format("{} must be a list of strings, not {}", what, KindName(entry.value.kind)));
    }
    std::vector<std::string> list;
    for (size_t i = 0; i < entry.value.items.size(); ++i) {
      const ConfigValue& item = entry.value.items[i];
      if (item.kind != Kind::kString) {
        Fail(item.line > 0 ? item.line : entry.line,
             fmt::format("{}[{}] must be a string, not {}", what, i, KindName(item.kind)));
      }
      list.push_back(item.text);
    }
    return list;
  }

  std::map<std::string, std::string> Environment(const ConfigEntry& entry,
                                                 const std::string& what) const {
    if (entry.value.kind != Kind::kTable) {
      Fail(LineOf(entry), fmt::format("{} must be a table of NAME = \"value\", not {}", what,
                                      KindName(entry.value.kind)));
    }
    std::map<std::string, std::string> env;
    for (const ConfigEntry& variable : entry.value.entries) {
      if (!IsEnvName(variable.key)) {
        Fail(variable.line, fmt::format("'{}' in {} is not a valid environment variable name "
                                        "(letters, digits and '_', not starting with a digit)",
                                        variable.key, what));
      }
      env[variable.key] = String(variable, fmt::format("{}.{}", what, variable.key));
    }
    return env;
  }

 private:
  static int LineOf(const ConfigEntry& entry) {
    return entry.value.line > 0 ? entry.value.line : entry.line;
  }
  static bool IsEnvName(const std::string& name) {
    if (name.empty() || std::isdigit(static_cast<unsigned char>(name[0]))) return false;
    return std::all_of(name.begin(), name.end(),
                       [](unsigned char c) { return std::isalnum(c) || c == '_'; });
  }

  std::string file_;
};

bool IsValidProcessName(const std::string& name) {
  if (name == "." || name == "..") return false;
  return std::all_of(name.begin(), name.end(), [](unsigned char c) {
    return std::isalnum(c) || c == '_' || c == '.' || c == '-';
  });
}

std::string Absolute(const fs::path& base, const std::string& path) {
  return (fs::path(path).is_absolute() ? fs::path(path) : base / path).lexically_normal().string();
}

ProcessSpec ReadProcess(const SchemaReader& reader, const ConfigValue& table,
                        const fs::path& base) {
  ProcessSpec process;
  process.line = table.line;
  reader.CheckKeys(table, kProcessKeys, "[[process]]");
  bool has_name = false;
  bool has_command = false;
  for (const ConfigEntry& entry : table.entries) {
    const int line = entry.value.line > 0 ? entry.value.line : entry.line;
    if (entry.key == "name") {
      process.name = reader.NonEmptyString(entry, "name");
      if (!IsValidProcessName(process.name)) {
        reader.Fail(line, fmt::format("process name '{}' may only use letters, digits, '_', '.' "
                                      "and '-' (it names the log file)",
                                      process.name));
      }
      has_name = true;
    } else if (entry.key == "command") {
      process.command = reader.NonEmptyString(entry, "command");
      if (process.command.find_first_of(" \t") != std::string::npos) {
        reader.Fail(line, fmt::format("command '{}' contains spaces: put the program in command "
                                      "and its arguments in args",
                                      process.command));
      }
      if (process.command.find('/') != std::string::npos) {
        process.command = Absolute(base, process.command);
      }
      process.command_line = line;
      has_command = true;
    } else if (entry.key == "args") {
      process.args = reader.StringList(entry, "args");
    } else if (entry.key == "host") {
      process.host = reader.String(entry, "host");
      if (process.host == "*" || Lower(process.host) == "localhost") process.host.clear();
    } else if (entry.key == "env") {
      process.env = reader.Environment(entry, "env");
    } else if (entry.key == "restart") {
      const std::string restart = reader.String(entry, "restart");
      if (restart == "always") {
        process.restart = RestartPolicy::kAlways;
      } else if (restart == "on-failure") {
        process.restart = RestartPolicy::kOnFailure;
      } else if (restart == "never") {
        process.restart = RestartPolicy::kNever;
      } else {
        reader.Fail(line, fmt::format("restart must be \"always\", \"on-failure\" or \"never\", "
                                      "not \"{}\"",
                                      restart));
      }
    } else if (entry.key == "stop_timeout") {
      const double seconds = reader.Number(entry, "stop_timeout");
      if (!std::isfinite(seconds) || seconds <= 0 || seconds > 3600) {
        reader.Fail(line, fmt::format("stop_timeout must be a number of seconds above 0 and at "
                                      "most 3600, not {}",
                                      seconds));
      }
      process.stop_timeout =
          std::chrono::milliseconds(std::max<int64_t>(1, std::llround(seconds * 1000)));
    } else if (entry.key == "working_dir") {
      process.working_dir = Absolute(base, reader.NonEmptyString(entry, "working_dir"));
    }
  }
  if (!has_name) reader.Fail(table.line, "this process has no name (add name = \"...\")");
  if (!has_command) {
    reader.Fail(table.line, fmt::format("process '{}' has no command", process.name));
  }
  return process;
}

std::string Extension(const std::string& file) {
  return Lower(fs::path(file).extension().string());
}

}  // namespace

const char* RestartPolicyName(RestartPolicy policy) {
  switch (policy) {
    case RestartPolicy::kAlways:
      return "always";
    case RestartPolicy::kOnFailure:
      return "on-failure";
    case RestartPolicy::kNever:
      return "never";
  }
  return "?";
}

LaunchSpec ParseLaunchFile(std::string_view text, const std::string& file) {
  const std::string extension = Extension(file);
  ConfigValue root;
  if (extension == ".toml") {
    root = ReadTomlTree(text, file);
  } else if (extension == ".yaml" || extension == ".yml") {
    root = ReadYamlTree(text, file);
  } else {
    throw LaunchFileError(file, 0,
                          "unknown launch file type '" + extension + "': use .toml, .yaml or .yml");
  }
  const SchemaReader reader(file);
  if (root.kind != Kind::kTable) {
    reader.Fail(root.line,
                fmt::format("a launch file is a table of keys, not {}", KindName(root.kind)));
  }
  reader.CheckKeys(root, kTopLevelKeys, "the launch file");

  const fs::path base = fs::absolute(fs::path(file)).parent_path();
  LaunchSpec spec;
  spec.file = file;
  spec.log_dir = Absolute(base, "logs");
  const ConfigEntry* processes = nullptr;
  for (const ConfigEntry& entry : root.entries) {
    if (entry.key == "log_dir") {
      spec.log_dir = Absolute(base, reader.NonEmptyString(entry, "log_dir"));
    } else if (entry.key == "env") {
      spec.env = reader.Environment(entry, "env");
    } else if (entry.key == "process") {
      processes = &entry;
    }
  }
  if (processes == nullptr) {
    reader.Fail(1,
                "no processes: add at least one [[process]] table (TOML) or 'process:' list "
                "(YAML)");
  }
  const int list_line = processes->value.line > 0 ? processes->value.line : processes->line;
  if (processes->value.kind != Kind::kArray) {
    reader.Fail(list_line, fmt::format("process must be a list of tables ([[process]]), not {}",
                                       KindName(processes->value.kind)));
  }
  if (processes->value.items.empty()) reader.Fail(list_line, "the process list is empty");

  std::map<std::string, int> name_lines;
  for (const ConfigValue& item : processes->value.items) {
    if (item.kind != Kind::kTable) {
      reader.Fail(item.line > 0 ? item.line : list_line,
                  fmt::format("each process must be a table, not {}", KindName(item.kind)));
    }
    ProcessSpec process = ReadProcess(reader, item, base);
    const auto name_entry = std::find_if(item.entries.begin(), item.entries.end(),
                                         [](const ConfigEntry& e) { return e.key == "name"; });
    const int name_line = name_entry->value.line > 0 ? name_entry->value.line : name_entry->line;
    if (auto [it, inserted] = name_lines.emplace(process.name, name_line); !inserted) {
      reader.Fail(name_line, fmt::format("duplicate process name '{}' (first used on line {})",
                                         process.name, it->second));
    }
    spec.processes.push_back(std::move(process));
  }
  return spec;
}

LaunchSpec LoadLaunchFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw LaunchFileError(path, 0, std::string("cannot read: ") + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw LaunchFileError(path, 0, "cannot read the file");
  return ParseLaunchFile(text.str(), path);
}

bool HostMatches(const std::string& process_host, const std::string& host) {
  if (process_host.empty()) return true;
  const std::string a = Lower(process_host);
  const std::string b = Lower(host);
  if (a == b) return true;
  auto short_name = [](const std::string& name) { return name.substr(0, name.find('.')); };
  return short_name(a) == short_name(b);
}

LaunchSpec ForHost(LaunchSpec spec, const std::string& host) {
  std::erase_if(spec.processes,
                [&](const ProcessSpec& process) { return !HostMatches(process.host, host); });
  return spec;
}

void ResolveCommands(LaunchSpec& spec, const fs::path& bin_dir) {
  for (ProcessSpec& process : spec.processes) {
    if (process.command.find('/') != std::string::npos) {
      if (!IsExecutableFile(process.command)) {
        throw LaunchFileError(spec.file, process.command_line,
                              fmt::format("command '{}' of process '{}' is not an executable file",
                                          process.command, process.name));
      }
      continue;
    }
    if (!bin_dir.empty() && IsExecutableFile(bin_dir / process.command)) {
      process.command = (bin_dir / process.command).string();
      continue;
    }
    // The PATH the process will see: its own env, the file's env, then ours.
    std::string path_list = "/usr/local/bin:/usr/bin:/bin";
    if (const char* path = std::getenv("PATH")) path_list = path;
    if (auto it = spec.env.find("PATH"); it != spec.env.end()) path_list = it->second;
    if (auto it = process.env.find("PATH"); it != process.env.end()) path_list = it->second;
    const std::string found = FindInPath(process.command, path_list);
    if (found.empty()) {
      throw LaunchFileError(
          spec.file, process.command_line,
          fmt::format("command '{}' of process '{}' was found neither in {} nor in PATH ({})",
                      process.command, process.name,
                      bin_dir.empty() ? std::string("the avc folder") : bin_dir.string(),
                      path_list));
    }
    process.command = fs::absolute(found).lexically_normal().string();
  }
}

}  // namespace avc::launch
