#pragma once

// The builder's shorthand flags (`avc builder`, `avc reconstruct`): each names options of the
// builder's table (services/builder/builder_options.h) and becomes their assignments, applied
// after --config and before --set.

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

namespace avc::cli {

struct BuilderShorthands {
  std::optional<std::string> method;  // method
  std::optional<std::string> masks;   // masks.method
  std::optional<int> level;           // patch.level and sweep.level
  std::optional<int> tolerance;       // proxy.background_votes_allowed
  std::optional<double> voxel_mm;     // proxy.final_voxel_size (m)

  // The flags given as assignments, followed by `sets`.
  std::vector<std::string> Settings(const std::vector<std::string>& sets) const;
};

// --level, --tolerance, --voxel-mm and the method under `method_flag` ("--method", "--mvs").
void AddBuilderShorthands(CLI::App* command, BuilderShorthands* flags,
                          const std::string& method_flag);

}  // namespace avc::cli
