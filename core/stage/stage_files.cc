#include "core/stage/stage_files.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "core/util/file_io.h"

namespace avc::stage {

namespace fs = std::filesystem;

std::vector<avc::file_t> PackFiles(const fs::path& root,
                                   const std::vector<std::string>& relative_paths) {
  std::vector<avc::file_t> files;
  files.reserve(relative_paths.size());
  for (const std::string& relative : relative_paths) {
    if (const std::string problem = RelativePathProblem(relative); !problem.empty()) {
      throw std::invalid_argument(fmt::format("cannot send '{}': {}", relative, problem));
    }
    const std::string bytes = ReadFile(root / relative);
    avc::file_t file;
    file.path = relative;
    file.data.assign(bytes.begin(), bytes.end());
    file.size = static_cast<int32_t>(file.data.size());
    files.push_back(std::move(file));
  }
  return files;
}

std::vector<avc::file_t> PackFolder(const fs::path& root) {
  std::vector<std::string> paths;
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(root)) {
    if (entry.is_regular_file())
      paths.push_back(entry.path().lexically_relative(root).generic_string());
  }
  std::sort(paths.begin(), paths.end());
  return PackFiles(root, paths);
}

std::string RelativePathProblem(const std::string& path) {
  if (path.empty()) return "the path is empty";
  if (path.find('\0') != std::string::npos) return "the path holds a NUL byte";
  const fs::path p(path);
  if (p.is_absolute() || path.front() == '/') return "the path is absolute";
  for (const fs::path& part : p) {
    if (part == ".." || part == ".") return "the path has a '.' or '..' part";
  }
  if (path.back() == '/') return "the path names a folder";
  return "";
}

void UnpackFiles(const std::vector<avc::file_t>& files, const fs::path& root) {
  for (const avc::file_t& file : files) {
    if (const std::string problem = RelativePathProblem(file.path); !problem.empty()) {
      throw std::invalid_argument(fmt::format("file '{}': {}", file.path, problem));
    }
    if (file.size < 0 || static_cast<size_t>(file.size) != file.data.size()) {
      throw std::invalid_argument(fmt::format("file '{}': size {} but {} bytes of data", file.path,
                                              file.size, file.data.size()));
    }
    const fs::path target = root / file.path;
    fs::create_directories(target.parent_path());
    WriteFileAtomically(target, std::string(file.data.begin(), file.data.end()));
  }
}

int64_t FileBytes(const std::vector<avc::file_t>& files) {
  int64_t bytes = 0;
  for (const avc::file_t& file : files) bytes += static_cast<int64_t>(file.data.size());
  return bytes;
}

}  // namespace avc::stage
