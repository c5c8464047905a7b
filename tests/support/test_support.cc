#include "tests/support/test_support.h"

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>

namespace avc::testing {

TempDir::TempDir(const std::string& prefix) {
  std::string pattern = (std::filesystem::temp_directory_path() / (prefix + "-XXXXXX")).string();
  if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed: " + pattern);
  path_ = pattern;
}

TempDir::~TempDir() {
  // AVC_KEEP_TEST_DIRS=1 keeps every test's files for a look after a failure.
  if (const char* keep = std::getenv("AVC_KEEP_TEST_DIRS"); keep != nullptr && *keep == '1') return;
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

namespace {
std::filesystem::path FromEnv(const char* name) {
  const char* value = std::getenv(name);
  if (value == nullptr || *value == '\0') {
    throw std::runtime_error(std::string(name) + " is not set; run the tests through ctest");
  }
  return value;
}
}  // namespace

std::filesystem::path BuildDir() { return FromEnv("AVC_BUILD_DIR"); }
std::filesystem::path SourceDir() { return FromEnv("AVC_SOURCE_DIR"); }
std::filesystem::path SharedDataDir() {
  if (const char* dir = std::getenv("AVC_SHARED_DATA"); dir != nullptr && *dir != '\0') {
    return dir;
  }
  return SourceDir() / ".." / "shared" / "data";
}
std::filesystem::path Executable(const std::string& name) { return BuildDir() / "bin" / name; }

std::string ReadFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

void WriteFile(const std::filesystem::path& path, const std::string& contents) {
  std::ofstream out(path, std::ios::binary);
  out << contents;
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

std::vector<uint8_t> RandomBytes(size_t size, uint32_t seed) {
  std::vector<uint8_t> bytes(size);
  std::mt19937 rng(seed);
  for (auto& b : bytes) b = static_cast<uint8_t>(rng());
  return bytes;
}

}  // namespace avc::testing
