#pragma once

#include <string>

namespace avc {

// This machine's host name ("unknown-host" if it cannot be read).
std::string HostName();

}  // namespace avc
