#include "core/util/file_io.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace avc {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void SystemFail(const std::string& action, const fs::path& path, int error) {
  throw std::runtime_error(fmt::format("{} {}: {}", action, path.string(), std::strerror(error)));
}

// Closes the descriptor on every exit path.
class Fd {
 public:
  explicit Fd(int fd) : fd_(fd) {}
  ~Fd() {
    if (fd_ >= 0) ::close(fd_);
  }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  int get() const { return fd_; }
  // Closes now and reports close's result (it can carry a delayed write error).
  int Close() {
    const int result = ::close(fd_);
    fd_ = -1;
    return result;
  }

 private:
  int fd_;
};

void WriteAll(int fd, std::string_view bytes, const fs::path& path) {
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) SystemFail("cannot write", path, errno);
    done += static_cast<size_t>(n);
  }
}

}  // namespace

std::string ReadFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) SystemFail("cannot read", path, errno);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (in.bad()) SystemFail("cannot read", path, errno);
  return bytes.str();
}

void WriteFileAtomically(const fs::path& path, std::string_view bytes) {
  const fs::path tmp = path.string() + ".tmp";
  {
    Fd file(::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644));
    if (file.get() < 0) SystemFail("cannot create", tmp, errno);
    try {
      WriteAll(file.get(), bytes, tmp);
      if (::fsync(file.get()) != 0) SystemFail("cannot sync", tmp, errno);
      if (file.Close() != 0) SystemFail("cannot close", tmp, errno);
      if (::rename(tmp.c_str(), path.c_str()) != 0) {
        SystemFail(fmt::format("cannot rename {} over", tmp.string()), path, errno);
      }
    } catch (...) {
      ::unlink(tmp.c_str());  // best effort: the error being thrown matters more
      throw;
    }
  }
  const fs::path dir = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  Fd directory(::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (directory.get() < 0) SystemFail("cannot open directory", dir, errno);
  if (::fsync(directory.get()) != 0) SystemFail("cannot sync directory", dir, errno);
}

}  // namespace avc
