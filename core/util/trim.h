#pragma once

// Text protocols (the UR dashboard and URScript, the LT360's replies) pad their lines with
// spaces, tabs, CR and LF.

#include <string_view>

namespace avc {

// `text` without leading and trailing spaces, tabs, CR and LF.
inline std::string_view TrimSpace(std::string_view text) {
  const size_t begin = text.find_first_not_of(" \t\r\n\f\v");
  if (begin == std::string_view::npos) return {};
  const size_t end = text.find_last_not_of(" \t\r\n\f\v");
  return text.substr(begin, end - begin + 1);
}

}  // namespace avc
