#pragma once

// Small helpers shared by the tests.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace avc::testing {

// A fresh, empty directory under the system temp dir, removed by the destructor (kept when
// AVC_KEEP_TEST_DIRS=1).
class TempDir {
 public:
  explicit TempDir(const std::string& prefix = "avc-test");
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

// The build tree (ctest sets AVC_BUILD_DIR) and the source tree (AVC_SOURCE_DIR).
std::filesystem::path BuildDir();
std::filesystem::path SourceDir();
// The project's shared real data (AVC_SHARED_DATA, else ../shared/data beside the source tree).
// Tests that need it skip with a message when it is absent.
std::filesystem::path SharedDataDir();
// build/bin/<name>: our executables.
std::filesystem::path Executable(const std::string& name);

std::string ReadFile(const std::filesystem::path& path);
void WriteFile(const std::filesystem::path& path, const std::string& contents);

// size seeded pseudo-random bytes (the same for the same seed).
std::vector<uint8_t> RandomBytes(size_t size, uint32_t seed);

// The LCM encoding of msg.
template <class T>
std::string Encode(const T& msg) {
  std::string bytes(static_cast<size_t>(msg.getEncodedSize()), '\0');
  msg.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

}  // namespace avc::testing
