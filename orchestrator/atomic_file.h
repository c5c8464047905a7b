#pragma once

// Files a scan must never lose half of: written beside the target, flushed to the disk, then
// renamed over it, and the directory flushed, so after a crash or a full disk the path holds
// either the old bytes or the new ones, never a torn mix.

#include <filesystem>
#include <string_view>

namespace avc::orchestrator {

// Throws std::runtime_error naming the path and the system's reason (e.g. "No space left on
// device"); the target is then unchanged and no temporary file is left behind.
void WriteFileAtomically(const std::filesystem::path& path, std::string_view bytes);

}  // namespace avc::orchestrator
