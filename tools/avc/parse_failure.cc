#include "tools/avc/parse_failure.h"

#include <vector>

namespace avc::cli {
namespace {

const CLI::App* DeepestSelected(const CLI::App& root) {
  const CLI::App* command = &root;
  while (!command->get_subcommands().empty()) command = command->get_subcommands().front();
  return command;
}

// CLI11 reports a missing subcommand rather than the word it could not place (`avc typo`).
std::string Problem(const CLI::App& command, const CLI::Error& error) {
  const std::vector<std::string> unplaced = command.remaining();
  const bool takes_subcommands = !command.get_subcommands({}).empty();
  if (!takes_subcommands || unplaced.empty()) return error.what();
  const std::string& word = unplaced.front();
  return (word.rfind('-', 0) == 0 ? "unknown option '" : "no command named '") + word + "'";
}

}  // namespace

std::string SelectedCommandPath(const CLI::App& root) {
  std::string path = "avc";
  for (const CLI::App* command = &root; !command->get_subcommands().empty();) {
    command = command->get_subcommands().front();
    path += " " + command->get_name();
  }
  return path;
}

std::string ParseFailureMessage(const CLI::App* root, const CLI::Error& error) {
  const std::string path = SelectedCommandPath(*root);
  return path + ": " + Problem(*DeepestSelected(*root), error) + "\nRun '" + path +
         " --help' for its options.\n";
}

}  // namespace avc::cli
