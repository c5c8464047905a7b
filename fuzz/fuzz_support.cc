#include "fuzz/fuzz_support.h"

#include <stdlib.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "core/geometry/mesh_io.h"
#include "core/geometry/point_cloud_io.h"

namespace avc::fuzz {
namespace fs = std::filesystem;
namespace {

// A broken harness must not pass for a rejected input: stop loudly.
[[noreturn]] void Die(const std::string& what) {
  std::fprintf(stderr, "fuzz_support: %s\n", what.c_str());
  std::abort();
}

// Removes the directory when the process ends normally (libFuzzer's -runs, -max_total_time).
struct OwnedDir {
  fs::path path;
  ~OwnedDir() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
};

fs::path MakeTempDir() {
  std::string pattern =
      (fs::temp_directory_path() / ("avc-fuzz-" + std::to_string(getpid()) + "-XXXXXX")).string();
  if (mkdtemp(pattern.data()) == nullptr) {
    Die("cannot create a directory like " + pattern + ": " + std::strerror(errno));
  }
  return pattern;
}

}  // namespace

std::string_view AsText(const uint8_t* data, size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

const fs::path& TempDir() {
  static const OwnedDir dir{MakeTempDir()};
  return dir.path;
}

fs::path FreshDir(const std::string& name) {
  const fs::path dir = TempDir() / name;
  std::error_code error;
  fs::remove_all(dir, error);
  if (!error) fs::create_directories(dir, error);
  if (error) Die("cannot recreate " + dir.string() + ": " + error.message());
  return dir;
}

fs::path WriteFile(const fs::path& dir, const std::string& name, std::string_view bytes) {
  const fs::path path = dir / name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) Die("cannot write " + path.string());
  return path;
}

std::vector<std::string_view> SplitParts(std::string_view text, size_t count) {
  std::vector<std::string_view> parts;
  while (parts.size() + 1 < count) {
    const size_t at = text.find(kPartSeparator);
    if (at == std::string_view::npos) break;
    parts.push_back(text.substr(0, at));
    text.remove_prefix(at + kPartSeparator.size());
  }
  parts.push_back(text);
  parts.resize(count);
  return parts;
}

void ReadMeshFile(const std::string& name, const uint8_t* data, size_t size) {
  const fs::path path = WriteFile(TempDir(), name, AsText(data, size));
  try {
    geometry::ReadMesh(path);
  } catch (const std::runtime_error&) {
  }
  try {
    geometry::ReadPointCloud(path);
  } catch (const std::runtime_error&) {
  }
  if (path.extension() == ".ply") {
    try {
      geometry::PlyHasFaces(path);
    } catch (const std::runtime_error&) {
    }
  }
}

}  // namespace avc::fuzz
