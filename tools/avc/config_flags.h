#pragma once

// --config FILE and --set SECTION.FIELD=VALUE for a command whose options are declared in an
// OptionTable (core/config/option_table.h); --help lists every option with its default.

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "core/config/option_table.h"

namespace avc::cli {

struct ConfigFlags {
  std::vector<std::string> files;              // --config, in order
  std::vector<config::Assignment> shorthands;  // from the shorthand flags, named by flag
  std::vector<std::string> sets;

  // Everything in the order it applies: the files, the shorthand flags given, then --set.
  // Throws config::ConfigError for a file that cannot be read or a malformed --set.
  std::vector<config::Assignment> Assignments() const;
};

// The table's defaults changed by the flags; throws config::ConfigError naming what is wrong
// and where (file and line, flag, or --set).
template <typename Options>
Options LoadOptions(const config::OptionTable<Options>& table, const ConfigFlags& flags,
                    Options defaults = {}) {
  table.Apply(defaults, flags.Assignments());
  return defaults;
}

// `reference` is the table's Reference(defaults).
void AddConfigFlags(CLI::App* command, ConfigFlags* flags, const std::string& reference);

// A flag standing for one option: `--flag VALUE` is `--set option=VALUE`, checked by the table.
void AddShorthand(CLI::App* command, ConfigFlags* flags, const std::string& flag,
                  const std::string& option, const std::string& help);
// A flag in other units than its option: `--flag VALUE` is `option=VALUE*scale` (a mm flag for
// an option in m), and a flag standing for several options takes `options`.
void AddScaledShorthand(CLI::App* command, ConfigFlags* flags, const std::string& flag,
                        const std::string& option, double scale, const std::string& help);
void AddShorthandForAll(CLI::App* command, ConfigFlags* flags, const std::string& flag,
                        const std::vector<std::string>& options, const std::string& help);
// A switch standing for `--set option=value`.
void AddShorthandSwitch(CLI::App* command, ConfigFlags* flags, const std::string& flag,
                        const std::string& option, const std::string& value,
                        const std::string& help);

}  // namespace avc::cli
