#pragma once

// Locating the programs a launcher starts: a PATH search and the folder of the running binary.

#include <filesystem>
#include <string>

namespace avc::launch {

// A regular file this process may execute.
bool IsExecutableFile(const std::filesystem::path& path);

// The first executable "<dir>/<name>" over the ':'-separated dirs of path_list (an empty entry
// is the current directory, as for execvp); empty when there is none.
std::string FindInPath(const std::string& name, const std::string& path_list);

// The folder holding the running executable, from /proc/self/exe; empty if unreadable.
std::filesystem::path SelfExecutableDir();

}  // namespace avc::launch
