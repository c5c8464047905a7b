#pragma once

// Every `avc` subcommand registers itself on the root app. A command's callback stores its
// process exit code in *exit_code; main returns it.

#include <CLI/CLI.hpp>

namespace avc::cli {

void RegisterVersion(CLI::App& root, int* exit_code);

}  // namespace avc::cli
