#pragma once

// The simulated scans the reconstruction benchmarks run on: a preset plant rendered from the
// paper's initial 3 x 10 views at 1280x960 with noise, kept under a work folder so that several
// benchmarks (or runs) can share them.

#include <filesystem>
#include <optional>
#include <string>

namespace avc::bench {

// work / preset, rendered there first (in a child process, so that the renderer's threads never
// run in the benchmark's process) unless it already holds a scan. nullopt, after saying why on
// stderr, when rendering fails.
std::optional<std::filesystem::path> EnsureSimulatedScan(const std::filesystem::path& work,
                                                         const std::string& preset);

}  // namespace avc::bench
