#pragma once

// --config FILE and --set SECTION.FIELD=VALUE for a command whose options are declared in an
// OptionTable (core/config/option_table.h); --help lists every option with its default.

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace avc::cli {

struct ConfigFlags {
  std::vector<std::string> files;       // --config, in order
  std::vector<std::string> shorthands;  // from AddShorthand flags, as assignments
  std::vector<std::string> sets;

  // What applies over --config: the shorthand flags given, then --set.
  std::vector<std::string> Settings() const;
};

// `reference` is the table's Reference(defaults).
void AddConfigFlags(CLI::App* command, ConfigFlags* flags, const std::string& reference);

// A flag standing for one option: `--flag VALUE` is `--set option=VALUE`, checked by the table.
void AddShorthand(CLI::App* command, ConfigFlags* flags, const std::string& flag,
                  const std::string& option, const std::string& help);
// A switch standing for `--set option=value`.
void AddShorthandSwitch(CLI::App* command, ConfigFlags* flags, const std::string& flag,
                        const std::string& option, const std::string& value,
                        const std::string& help);

}  // namespace avc::cli
