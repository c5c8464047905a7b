#pragma once

// The builder's shorthand flags (`avc builder`, `avc reconstruct`): --level, --tolerance,
// --voxel-mm and the MVS method under `method_flag` ("--method", "--mvs"), each standing for
// options of the builder's table (services/builder/builder_options.h), applied after --config
// and before --set.

#include <CLI/CLI.hpp>
#include <string>

#include "tools/avc/config_flags.h"

namespace avc::cli {

void AddBuilderShorthands(CLI::App* command, ConfigFlags* flags, const std::string& method_flag);

}  // namespace avc::cli
