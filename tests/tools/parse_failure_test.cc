#include "tools/avc/parse_failure.h"

#include <gtest/gtest.h>

#include <string>

namespace avc::cli {
namespace {

// A small command tree shaped like avc's: a root that needs a subcommand, a command with a
// required option, and a command with subcommands of its own.
struct Tree {
  CLI::App root{"root"};
  std::string dataset;
  Tree() {
    root.require_subcommand(1);
    root.add_subcommand("reconstruct", "Reconstruct.")
        ->add_option("--dataset", dataset)
        ->required();
    CLI::App* sim = root.add_subcommand("sim", "The simulated cell.");
    sim->require_subcommand(1);
    sim->add_subcommand("render", "Render.");
  }

  // The message the command line gets (empty when it parses).
  std::string MessageFor(const std::string& command_line) {
    try {
      root.parse(command_line, /*program_name_included=*/false);
    } catch (const CLI::ParseError& error) {
      return ParseFailureMessage(&root, error);
    }
    return {};
  }
};

TEST(ParseFailure, NamesTheCommandAndItsHelp) {
  EXPECT_EQ(Tree().MessageFor("reconstruct"),
            "avc reconstruct: --dataset is required\n"
            "Run 'avc reconstruct --help' for its options.\n");
}

TEST(ParseFailure, AMistypedCommandIsNamed) {
  EXPECT_EQ(Tree().MessageFor("recontsruct"),
            "avc: no command named 'recontsruct'\nRun 'avc --help' for its options.\n");
  EXPECT_EQ(Tree().MessageFor("sim rendr"),
            "avc sim: no command named 'rendr'\nRun 'avc sim --help' for its options.\n");
  EXPECT_EQ(Tree().MessageFor("--verbose"),
            "avc: unknown option '--verbose'\nRun 'avc --help' for its options.\n");
}

TEST(ParseFailure, TheSelectedPathIsDeepestLast) {
  Tree tree;
  EXPECT_EQ(tree.MessageFor("sim render"), "");
  EXPECT_EQ(SelectedCommandPath(tree.root), "avc sim render");
}

}  // namespace
}  // namespace avc::cli
