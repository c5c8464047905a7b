#include "tools/avc/help_formatter.h"

#include <algorithm>
#include <sstream>

namespace avc::cli {

std::string CommandSummary(const std::string& description) {
  std::string text = description;
  std::replace(text.begin(), text.end(), '\n', ' ');
  text = text.substr(0, text.find(". "));  // the first sentence
  if (text.size() > kSummaryLength) {
    text = text.substr(0, std::min(text.find(": "), text.find("; ")));  // its first clause
  }
  while (!text.empty() && (text.back() == ' ' || text.back() == '.')) text.pop_back();
  return text;
}

std::string SummaryListingFormatter::make_subcommand(const CLI::App* sub) const {
  std::stringstream out;
  CLI::detail::format_help(out, sub->get_display_name(true), CommandSummary(sub->get_description()),
                           column_width_);
  return out.str();
}

}  // namespace avc::cli
