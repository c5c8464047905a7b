#include "tools/avc/parse_failure.h"

#include <vector>

namespace avc::cli {
namespace {

// root, then each subcommand selected under the previous one.
std::vector<const CLI::App*> SelectedChain(const CLI::App& root) {
  std::vector<const CLI::App*> chain = {&root};
  while (!chain.back()->get_subcommands().empty()) {
    chain.push_back(chain.back()->get_subcommands().front());
  }
  return chain;
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
  const std::vector<const CLI::App*> chain = SelectedChain(root);
  for (size_t k = 1; k < chain.size(); ++k) path += " " + chain[k]->get_name();
  return path;
}

std::string ParseFailureMessage(const CLI::App* root, const CLI::Error& error) {
  const std::string path = SelectedCommandPath(*root);
  return path + ": " + Problem(*SelectedChain(*root).back(), error) + "\nRun '" + path +
         " --help' for its options.\n";
}

}  // namespace avc::cli
