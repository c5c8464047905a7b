#pragma once

// A stage job's folders as file_t lists: what the orchestrator sends a stage and what the stage
// sends back. Paths are relative, with '/' separators, never absolute and never leaving the
// folder ("..") so a malformed or hostile job cannot write outside its own work folder.

#include <avc/file_t.hpp>
#include <filesystem>
#include <string>
#include <vector>

namespace avc::stage {

// A stage job or result of tens of megabytes goes in chunks of this size: a receive buffer of a few
// megabytes holds one, a lost fragment costs one chunk, and a recording of the scan plays back
// into fresh services (lcm-logplayer cannot resend what a socket dropped).
inline constexpr size_t kStageChunkBytes = 1'000'000;

// The named files under `root` (relative paths), in that order. Throws std::runtime_error naming
// a file that cannot be read.
std::vector<avc::file_t> PackFiles(const std::filesystem::path& root,
                                   const std::vector<std::string>& relative_paths);

// Every regular file under `root`, recursively, sorted by path (so the same folder gives the
// same list).
std::vector<avc::file_t> PackFolder(const std::filesystem::path& root);

// Empty when `path` is a usable relative path, else why not.
std::string RelativePathProblem(const std::string& path);

// Writes `files` under `root` (folders created). Throws std::invalid_argument naming the file for
// a bad path or a size that is not its data's, std::runtime_error when it cannot be written.
void UnpackFiles(const std::vector<avc::file_t>& files, const std::filesystem::path& root);

// Total bytes of the files' data.
int64_t FileBytes(const std::vector<avc::file_t>& files);

}  // namespace avc::stage
