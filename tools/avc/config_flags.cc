#include "tools/avc/config_flags.h"

namespace avc::cli {

std::vector<std::string> ConfigFlags::Settings() const {
  std::vector<std::string> settings = shorthands;
  settings.insert(settings.end(), sets.begin(), sets.end());
  return settings;
}

void AddConfigFlags(CLI::App* command, ConfigFlags* flags, const std::string& reference) {
  command
      ->add_option("--config", flags->files,
                   "options from a TOML file ([section] tables of field = value; a scan folder's "
                   "config/<service>.toml is one); repeatable, later files win")
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
          [flags, option](const std::string& value) {
            flags->shorthands.push_back(option + "=" + value);
          },
          help + " (" + option + ")")
      ->type_name("VALUE");
}

void AddShorthandSwitch(CLI::App* command, ConfigFlags* flags, const std::string& flag,
                        const std::string& option, const std::string& value,
                        const std::string& help) {
  command->add_flag_callback(
      flag, [flags, option, value] { flags->shorthands.push_back(option + "=" + value); },
      help + " (" + option + "=" + value + ")");
}

}  // namespace avc::cli
