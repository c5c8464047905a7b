#pragma once

// YAML config files for the options mechanism (option_table.h), beside TOML: a lab that keeps
// its cell's settings in YAML (as calibration.yaml is) writes nested maps of scalars, read as
// the same dotted assignments a TOML file gives.

#include <string>
#include <string_view>
#include <vector>

#include "core/config/option_text.h"

namespace avc::config {

// Every scalar of a YAML document as an assignment: nested maps give dotted names
// (surface: {fit: {degree: 2}} -> "surface.fit.degree"), in the document's order; `where` is
// "file:line". Sequences, empty values and syntax errors throw ConfigError naming the line.
std::vector<Assignment> ReadYamlAssignments(std::string_view text, const std::string& file);

}  // namespace avc::config
