#include "tools/avc/config_flags.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>

#include "core/config/option_text.h"

namespace avc::cli {
namespace {

// "--device,-d" -> "--device": how an error names the flag.
std::string FlagName(const std::string& flag) { return flag.substr(0, flag.find(',')); }

}  // namespace

std::vector<config::Assignment> ConfigFlags::Assignments() const {
  std::vector<config::Assignment> all = config::ReadAssignments(files, {});
  all.insert(all.end(), shorthands.begin(), shorthands.end());
  for (config::Assignment& set : config::ReadAssignments({}, sets)) all.push_back(std::move(set));
  return all;
}

void AddConfigFlags(CLI::App* command, ConfigFlags* flags, const std::string& reference) {
  command
      ->add_option("--config", flags->files,
                   "options from a TOML file ([section] tables of field = value; a scan folder's "
                   "config/<service>.toml is one) or a YAML one (.yaml, .yml: nested maps); "
                   "repeatable, later files win")
      ->check(CLI::ExistingFile);
  command
      ->add_option("--set", flags->sets,
                   "set one option, after --config and the flags above (repeatable)")
      ->type_name("SECTION.FIELD=VALUE");
  command->footer("Options (--config / --set), with their defaults:\n" + reference);
}

void AddShorthand(CLI::App* command, ConfigFlags* flags, const std::string& flag,
                  const std::string& option, const std::string& help) {
  command
      ->add_option_function<std::string>(
          flag,
          [flags, name = FlagName(flag), option](const std::string& value) {
            flags->shorthands.push_back({option, value, name});
          },
          help + " (" + option + ")")
      ->type_name("VALUE");
}

void AddShorthandSwitch(CLI::App* command, ConfigFlags* flags, const std::string& flag,
                        const std::string& option, const std::string& value,
                        const std::string& help) {
  command->add_flag_callback(
      flag,
      [flags, name = FlagName(flag), option, value] {
        flags->shorthands.push_back({option, value, name});
      },
      help + " (" + option + "=" + value + ")");
}

void AddScaledShorthand(CLI::App* command, ConfigFlags* flags, const std::string& flag,
                        const std::string& option, double scale, const std::string& help) {
  command->add_option_function<double>(
      flag,
      [flags, name = FlagName(flag), option, scale](double value) {
        // A whole result reads as an integer too (seconds given for an option in ms).
        const double scaled = value * scale;
        const bool whole = std::abs(scaled) < 1e15 && scaled == std::round(scaled);
        flags->shorthands.push_back(
            {option,
             whole ? fmt::format("{}", static_cast<int64_t>(scaled)) : config::RealText(scaled),
             name});
      },
      help + " (" + option + ")");
}

void AddShorthandForAll(CLI::App* command, ConfigFlags* flags, const std::string& flag,
                        const std::vector<std::string>& options, const std::string& help) {
  std::string names;
  for (const std::string& option : options) names += (names.empty() ? "" : " and ") + option;
  command
      ->add_option_function<std::string>(
          flag,
          [flags, name = FlagName(flag), options](const std::string& value) {
            for (const std::string& option : options) {
              flags->shorthands.push_back({option, value, name});
            }
          },
          help + " (" + names + ")")
      ->type_name("VALUE");
}

}  // namespace avc::cli
