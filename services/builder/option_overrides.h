#pragma once

// Named overrides of the builder's parameters ("patch.window=7", "proxy.background_votes_allowed
// =2", ...), so every setting can be changed from the command line or a config without a flag of
// its own. The names are the option structs' field names behind their section.

#include <string>
#include <vector>

#include "services/builder/reconstruction.h"

namespace avc::builder {

// Applies one "section.field=value" override. Throws std::invalid_argument naming the override
// for an unknown name, a malformed value, or (after applying) a value the options refuse.
void ApplyOverride(const std::string& assignment, ReconstructOptions* options);

// Every name ApplyOverride accepts, sorted, for --help and error messages.
std::vector<std::string> OverrideNames();

}  // namespace avc::builder
