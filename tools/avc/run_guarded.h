#pragma once

// The one way a subcommand runs: its callback stores run()'s exit code in *exit_code, and an
// exception becomes "avc NAME: message" on stderr with exit code 1, so bad input never crashes
// the CLI.

#include <CLI/CLI.hpp>
#include <functional>

namespace avc::cli {

// Runs `run` when the command is invoked (not when one of its subcommands is), turning an
// exception into "avc NAME: message" on stderr and exit code 1.
void SetGuardedRun(CLI::App* command, int* exit_code, std::function<int()> run);

}  // namespace avc::cli
