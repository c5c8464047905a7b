#include "core/auth/command_key.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <openssl/rand.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>

namespace avc::auth {
namespace {

namespace fs = std::filesystem;

constexpr size_t kHexDigits = 64;
constexpr char kHex[] = "0123456789abcdef";

std::string FromEnv(const char* name) {
  const char* value = std::getenv(name);
  return value ? value : "";
}

int HexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  const int lower = std::tolower(static_cast<unsigned char>(c));
  if (lower >= 'a' && lower <= 'f') return lower - 'a' + 10;
  return -1;
}

std::string SystemError() { return std::strerror(errno); }

}  // namespace

fs::path DefaultKeyFile(std::string_view cell) {
  const std::string name = std::string(cell) + ".key";
  if (const std::string dir = FromEnv("AVC_KEY_DIR"); !dir.empty()) return fs::path(dir) / name;
  if (const std::string config = FromEnv("XDG_CONFIG_HOME"); !config.empty()) {
    return fs::path(config) / "avc" / "keys" / name;
  }
  return fs::path(FromEnv("HOME")) / ".config" / "avc" / "keys" / name;
}

CommandKey LoadCommandKey(const fs::path& file) {
  // Opened once and checked through the descriptor, so the file checked is the file read.
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
  if (fd < 0) {
    throw KeyError(fmt::format("cannot open the command key {}: {}", file.string(), SystemError()));
  }
  struct stat info {};
  std::string text(kHexDigits + 2, '\0');
  ssize_t size = -1;
  if (::fstat(fd, &info) == 0 && S_ISREG(info.st_mode) && (info.st_mode & 077) == 0 &&
      info.st_uid == ::geteuid()) {
    size = ::read(fd, text.data(), text.size());
  }
  ::close(fd);
  if (!S_ISREG(info.st_mode)) {
    throw KeyError(fmt::format("command key {} is not a regular file", file.string()));
  }
  if ((info.st_mode & 077) != 0) {
    throw KeyError(fmt::format(
        "command key {} can be read or written by others (mode {:o}): not used; run chmod 600 {}",
        file.string(), info.st_mode & 0777, file.string()));
  }
  if (info.st_uid != ::geteuid()) {
    throw KeyError(fmt::format("command key {} belongs to uid {}, not to this user (uid {})",
                               file.string(), info.st_uid, ::geteuid()));
  }
  if (size < 0) {
    throw KeyError(fmt::format("cannot read the command key {}: {}", file.string(), SystemError()));
  }
  text.resize(static_cast<size_t>(size));
  if (!text.empty() && text.back() == '\n') text.pop_back();
  CommandKey key;
  key.file = file;
  bool hex = text.size() == kHexDigits;
  for (size_t i = 0; hex && i < key.bytes.size(); ++i) {
    const int high = HexValue(text[2 * i]);
    const int low = HexValue(text[2 * i + 1]);
    hex = high >= 0 && low >= 0;
    key.bytes[i] = static_cast<uint8_t>(high * 16 + low);
  }
  if (!hex) {
    throw KeyError(
        fmt::format("command key {} is not 64 hex digits; make a new one with `avc key generate`",
                    file.string()));
  }
  return key;
}

std::optional<CommandKey> FindCommandKey(std::string_view cell) {
  const fs::path file = DefaultKeyFile(cell);
  std::error_code error;
  if (!fs::exists(fs::symlink_status(file, error))) return std::nullopt;
  return LoadCommandKey(file);
}

CommandKey GenerateCommandKey(const fs::path& file) {
  CommandKey key;
  key.file = file;
  if (RAND_bytes(key.bytes.data(), static_cast<int>(key.bytes.size())) != 1) {
    throw KeyError("cannot make a command key: OpenSSL's random generator failed");
  }
  if (file.has_parent_path() && !fs::exists(file.parent_path())) {
    std::error_code error;
    fs::create_directories(file.parent_path(), error);
    if (error) {
      throw KeyError(
          fmt::format("cannot create {}: {}", file.parent_path().string(), error.message()));
    }
    fs::permissions(file.parent_path(), fs::perms::owner_all, error);
  }
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0) {
    throw KeyError(errno == EEXIST
                       ? fmt::format("{} exists already: a key is never overwritten (delete it "
                                     "first to replace the cell's key on every machine)",
                                     file.string())
                       : fmt::format("cannot create {}: {}", file.string(), SystemError()));
  }
  std::string text;
  for (uint8_t byte : key.bytes) {
    text += kHex[byte >> 4];
    text += kHex[byte & 15];
  }
  text += '\n';
  const bool written = ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size()) &&
                       ::fsync(fd) == 0;
  const std::string why = written ? "" : SystemError();
  ::close(fd);
  if (!written) {
    std::error_code ignored;
    fs::remove(file, ignored);
    throw KeyError(fmt::format("cannot write {}: {}", file.string(), why));
  }
  return key;
}

CommandKey LoadOrGenerateCommandKey(const fs::path& file) {
  std::error_code error;
  if (fs::exists(fs::symlink_status(file, error))) return LoadCommandKey(file);
  return GenerateCommandKey(file);
}

}  // namespace avc::auth
