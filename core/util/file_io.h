#pragma once

// Whole files in and out. WriteFileAtomically is for files that must never be half written (a
// scan's record and images): the bytes go beside the target, are flushed to the disk, then renamed
// over it, and the directory is flushed, so after a crash or a full disk the path holds either
// the old bytes or the new ones, never a torn mix.

#include <filesystem>
#include <string>
#include <string_view>

namespace avc {

// The file's bytes. Throws std::runtime_error("cannot read PATH: reason").
std::string ReadFile(const std::filesystem::path& path);

// Throws std::runtime_error naming the path and the system's reason (e.g. "No space left on
// device"); the target is then unchanged and no temporary file is left behind.
void WriteFileAtomically(const std::filesystem::path& path, std::string_view bytes);

}  // namespace avc
