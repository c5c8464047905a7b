#pragma once

// What `avc` prints when its command line does not parse: the command that was being parsed,
// the problem, and where its options are documented, e.g.
//   avc reconstruct: --dataset is required
//   Run 'avc reconstruct --help' for its options.
// (CLI11's own message names neither the command nor its help.)

#include <CLI/CLI.hpp>
#include <string>

namespace avc::cli {

// "avc" followed by the subcommands selected so far under root, deepest last.
std::string SelectedCommandPath(const CLI::App& root);

// For CLI::App::failure_message on the root command.
std::string ParseFailureMessage(const CLI::App* root, const CLI::Error& error);

}  // namespace avc::cli
