#pragma once

#include <cstddef>
#include <functional>
#include <string>

namespace avc::mvs {

// Progress callback shared by the MVS back ends: called with a stage name and how many of the
// stage's work items are done out of the total. May be empty (no reporting).
using MvsProgress = std::function<void(const std::string& stage, size_t done, size_t total)>;

}  // namespace avc::mvs
