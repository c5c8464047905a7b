#pragma once

// How `avc ... --help` lists subcommands. A command's description is wrapped prose whose first
// line usually ends mid-sentence, so a listing shows the command's summary instead: its first
// sentence, or that sentence's first clause when it is long. The command's own help prints the
// whole description, unchanged.

#include <CLI/CLI.hpp>
#include <cstddef>
#include <string>

namespace avc::cli {

// A first sentence longer than this is cut at the end of its first clause.
inline constexpr size_t kSummaryLength = 80;

// The description's first sentence (up to ". "), line breaks read as spaces, without its final
// "."; when that is longer than kSummaryLength, only its first clause (up to ": " or "; ").
std::string CommandSummary(const std::string& description);

// CLI11's formatter with subcommand listings shortened to CommandSummary. Set it on the root
// command before adding subcommands: each inherits its parent's formatter when it is created.
class SummaryListingFormatter : public CLI::Formatter {
 public:
  std::string make_subcommand(const CLI::App* sub) const override;
};

}  // namespace avc::cli
