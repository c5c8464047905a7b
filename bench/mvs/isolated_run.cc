#include "bench/mvs/isolated_run.h"

#include <fmt/format.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace avc::bench {
namespace {

void WriteAll(int fd, const std::string& bytes) {
  size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    written += static_cast<size_t>(n);
  }
}

std::string ReadAll(int fd) {
  std::string bytes;
  char buffer[65536];
  for (;;) {
    const ssize_t n = read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return bytes;
    bytes.append(buffer, static_cast<size_t>(n));
  }
}

}  // namespace

IsolatedResult RunIsolated(const std::function<nlohmann::json()>& run_case) {
  IsolatedResult outcome;
  int pipe_fds[2];
  if (pipe(pipe_fds) != 0) {
    outcome.error = std::string("pipe: ") + std::strerror(errno);
    return outcome;
  }
  const pid_t child = fork();
  if (child < 0) {
    outcome.error = std::string("fork: ") + std::strerror(errno);
    close(pipe_fds[0]);
    close(pipe_fds[1]);
    return outcome;
  }
  if (child == 0) {
    close(pipe_fds[0]);
    nlohmann::json message;
    try {
      message = {{"ok", true}, {"result", run_case()}};
    } catch (const std::exception& e) {
      message = {{"ok", false}, {"error", e.what()}};
    }
    WriteAll(pipe_fds[1], message.dump());
    close(pipe_fds[1]);
    _exit(0);
  }
  close(pipe_fds[1]);
  const std::string bytes = ReadAll(pipe_fds[0]);
  close(pipe_fds[0]);
  int status = 0;
  rusage usage{};
  while (wait4(child, &status, 0, &usage) < 0 && errno == EINTR) {
  }
  outcome.peak_memory_mb = static_cast<double>(usage.ru_maxrss) / 1024.0;
  if (WIFSIGNALED(status)) {
    outcome.error = fmt::format("the case was killed by signal {}", WTERMSIG(status));
    return outcome;
  }
  const nlohmann::json message = nlohmann::json::parse(bytes, nullptr, /*allow_exceptions=*/false);
  if (message.is_discarded() || !message.contains("ok")) {
    outcome.error = fmt::format("the case exited with status {} without a result",
                                WIFEXITED(status) ? WEXITSTATUS(status) : -1);
    return outcome;
  }
  outcome.ok = message["ok"].get<bool>();
  if (outcome.ok) {
    outcome.result = message["result"];
  } else {
    outcome.error = message["error"].get<std::string>();
  }
  return outcome;
}

}  // namespace avc::bench
