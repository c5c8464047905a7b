#pragma once

#include <string_view>

namespace avc {

// "<project version>+<git describe>" fixed at configure time.
std::string_view Version();

}  // namespace avc
