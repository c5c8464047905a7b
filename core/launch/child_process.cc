#include "core/launch/child_process.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <stdexcept>
#include <utility>

#include "core/launch/find_program.h"
#include "core/util/log.h"

namespace avc::launch {
namespace {

constexpr char kDefaultPath[] = "/usr/local/bin:/usr/bin:/bin";

// What the child reports through the CLOEXEC pipe when it cannot exec.
struct ExecFailure {
  int stage;
  int error;
};
enum Stage : int { kStageSetup = 1, kStageChdir = 2, kStageExec = 3 };

std::string ErrnoText(int error) { return std::strerror(error); }

std::map<std::string, std::string> MergedEnvironment(
    const std::map<std::string, std::string>& extra) {
  std::map<std::string, std::string> env;
  for (char** entry = environ; entry != nullptr && *entry != nullptr; ++entry) {
    const std::string text(*entry);
    const size_t eq = text.find('=');
    if (eq == std::string::npos) continue;
    env[text.substr(0, eq)] = text.substr(eq + 1);
  }
  for (const auto& [key, value] : extra) env[key] = value;
  return env;
}

int OpenOrThrow(const std::string& program, const std::string& path, int flags, const char* what) {
  const int fd = open(path.c_str(), flags | O_CLOEXEC, 0644);
  if (fd < 0) {
    throw std::runtime_error("cannot start '" + program + "': cannot open " + what + " '" + path +
                             "': " + ErrnoText(errno));
  }
  return fd;
}

// A descriptor another thread opened without O_CLOEXEC (a library's socket, a bound port) must
// not live on in the child: it would keep the port or pipe open for the child's whole life.
// Everything above stderr becomes close-on-exec, so the failure report pipe still works until
// exec. Async-signal-safe; kernels before 5.11 lack CLOSE_RANGE_CLOEXEC, so fcntl each one.
void MarkInheritedDescriptorsCloseOnExec() {
  if (close_range(STDERR_FILENO + 1, ~0U, CLOSE_RANGE_CLOEXEC) == 0) return;
  rlimit limit{};
  const int max_fd = getrlimit(RLIMIT_NOFILE, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY
                         ? static_cast<int>(std::min<rlim_t>(limit.rlim_cur, 1 << 20))
                         : 1 << 16;
  for (int fd = STDERR_FILENO + 1; fd < max_fd; ++fd) fcntl(fd, F_SETFD, FD_CLOEXEC);
}

// Runs in the child between fork and exec: async-signal-safe calls only.
[[noreturn]] void ExecChild(int report_fd, int stdin_fd, int log_fd, const char* working_dir,
                            const char* exe, char* const* argv, char* const* envp, pid_t parent) {
  auto fail = [report_fd](int stage) {
    const ExecFailure failure{stage, errno};
    [[maybe_unused]] ssize_t n = write(report_fd, &failure, sizeof(failure));
    _exit(127);
  };
  // Handlers installed by the parent (the event loop's self-pipe) must not run in the child.
  struct sigaction default_action {};
  default_action.sa_handler = SIG_DFL;
  sigemptyset(&default_action.sa_mask);
  for (int signo = 1; signo < NSIG; ++signo) sigaction(signo, &default_action, nullptr);
  if (setpgid(0, 0) != 0) fail(kStageSetup);
  if (prctl(PR_SET_PDEATHSIG, SIGTERM) != 0) fail(kStageSetup);
  // The parent may have died before prctl took effect.
  if (getppid() != parent) _exit(127);
  sigset_t empty;
  sigemptyset(&empty);
  sigprocmask(SIG_SETMASK, &empty, nullptr);
  if (dup2(stdin_fd, STDIN_FILENO) < 0) fail(kStageSetup);
  if (log_fd >= 0 && (dup2(log_fd, STDOUT_FILENO) < 0 || dup2(log_fd, STDERR_FILENO) < 0)) {
    fail(kStageSetup);
  }
  MarkInheritedDescriptorsCloseOnExec();
  if (working_dir != nullptr && chdir(working_dir) != 0) fail(kStageChdir);
  execve(exe, argv, envp);
  fail(kStageExec);
  _exit(127);  // fail() never returns, but a lambda cannot say so
}

}  // namespace

ChildProcess ChildProcess::Spawn(const SpawnSpec& spec) {
  if (spec.argv.empty() || spec.argv[0].empty()) {
    throw std::runtime_error("cannot start a process: the command is empty");
  }
  const std::string& program = spec.argv[0];
  const std::map<std::string, std::string> env = MergedEnvironment(spec.env);

  std::string exe = program;
  if (program.find('/') == std::string::npos) {
    const auto path = env.find("PATH");
    const std::string path_list = path != env.end() ? path->second : kDefaultPath;
    exe = FindInPath(program, path_list);
    if (exe.empty()) {
      throw std::runtime_error("cannot start '" + program + "': " + ErrnoText(ENOENT) +
                               " (not found in PATH=" + path_list + ")");
    }
  }

  // Everything the child needs is built before fork: it may not allocate afterwards.
  std::vector<std::string> env_strings;
  env_strings.reserve(env.size());
  for (const auto& [key, value] : env) env_strings.push_back(key + "=" + value);
  std::vector<char*> envp;
  for (std::string& entry : env_strings) envp.push_back(entry.data());
  envp.push_back(nullptr);
  std::vector<std::string> argv_strings = spec.argv;
  std::vector<char*> argv;
  for (std::string& arg : argv_strings) argv.push_back(arg.data());
  argv.push_back(nullptr);

  const int stdin_fd = OpenOrThrow(program, "/dev/null", O_RDONLY, "stdin");
  int log_fd = -1;
  try {
    if (!spec.log_file.empty()) {
      log_fd = OpenOrThrow(program, spec.log_file, O_WRONLY | O_CREAT | O_APPEND, "log file");
    }
  } catch (...) {
    close(stdin_fd);
    throw;
  }
  int report[2];
  if (pipe2(report, O_CLOEXEC) != 0) {
    const int error = errno;
    close(stdin_fd);
    if (log_fd >= 0) close(log_fd);
    throw std::runtime_error("cannot start '" + program + "': pipe: " + ErrnoText(error));
  }

  // Signals stay blocked across fork so no parent handler runs in the child before reset.
  sigset_t all, previous;
  sigfillset(&all);
  pthread_sigmask(SIG_SETMASK, &all, &previous);
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid == 0) {
    close(report[0]);
    ExecChild(report[1], stdin_fd, log_fd,
              spec.working_dir.empty() ? nullptr : spec.working_dir.c_str(), exe.c_str(),
              argv.data(), envp.data(), parent);
  }
  const int fork_error = errno;
  pthread_sigmask(SIG_SETMASK, &previous, nullptr);
  close(report[1]);
  close(stdin_fd);
  if (log_fd >= 0) close(log_fd);
  if (pid < 0) {
    close(report[0]);
    throw std::runtime_error("cannot start '" + program + "': fork: " + ErrnoText(fork_error));
  }
  // Also set here so the group exists whichever of parent and child runs first.
  setpgid(pid, pid);

  ExecFailure failure{};
  ssize_t got = 0;
  do {
    got = read(report[0], &failure, sizeof(failure));
  } while (got < 0 && errno == EINTR);
  close(report[0]);
  ChildProcess child(pid);
  if (got <= 0) return child;  // EOF: exec closed the pipe

  child.WaitFor(std::chrono::seconds(5));
  std::string what;
  switch (failure.stage) {
    case kStageChdir:
      what = "cannot change to working directory '" + spec.working_dir + "'";
      break;
    case kStageExec:
      what = "cannot execute '" + exe + "'";
      break;
    default:
      what = "cannot set up the child process";
  }
  throw std::runtime_error("cannot start '" + program + "': " + what + ": " +
                           ErrnoText(failure.error));
}

ChildProcess::ChildProcess(ChildProcess&& other) noexcept
    : pid_(std::exchange(other.pid_, 0)), status_(std::exchange(other.status_, std::nullopt)) {}

ChildProcess& ChildProcess::operator=(ChildProcess&& other) noexcept {
  if (this != &other) {
    KillAndReap();
    pid_ = std::exchange(other.pid_, 0);
    status_ = std::exchange(other.status_, std::nullopt);
  }
  return *this;
}

ChildProcess::~ChildProcess() { KillAndReap(); }

void ChildProcess::KillAndReap() {
  if (pid_ <= 0 || status_) return;
  if (kill(-pid_, SIGKILL) != 0) kill(pid_, SIGKILL);
  int status = 0;
  pid_t reaped = 0;
  do {
    reaped = waitpid(pid_, &status, 0);
  } while (reaped < 0 && errno == EINTR);
  status_ = status;
}

bool ChildProcess::running() const {
  if (pid_ <= 0 || status_) return false;
  siginfo_t info{};
  // WNOWAIT: look without reaping, so the status is still there for TryWait.
  if (waitid(P_PID, static_cast<id_t>(pid_), &info, WEXITED | WNOHANG | WNOWAIT) != 0) {
    return false;
  }
  return info.si_pid == 0;
}

bool ChildProcess::Signal(int signo) {
  if (pid_ <= 0 || status_) return false;
  return kill(-pid_, signo) == 0;
}

std::optional<int> ChildProcess::TryWait() {
  if (status_ || pid_ <= 0) return status_;
  int status = 0;
  pid_t reaped = 0;
  do {
    reaped = waitpid(pid_, &status, WNOHANG);
  } while (reaped < 0 && errno == EINTR);
  if (reaped == pid_) {
    status_ = status;
  } else if (reaped < 0 && errno == ECHILD) {
    // Someone else reaped it (waitpid(-1) elsewhere): it is gone, its status lost.
    log::Warn("child {} was reaped elsewhere; its exit status is unknown", pid_);
    status_ = 255 << 8;
  }
  return status_;
}

std::optional<int> ChildProcess::WaitFor(std::chrono::milliseconds timeout) {
  if (TryWait() || pid_ <= 0) return status_;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  // A pidfd becomes readable when the child exits; without one (old kernels), poll briefly.
  const int pidfd = static_cast<int>(syscall(SYS_pidfd_open, pid_, 0));
  while (!TryWait()) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) break;
    if (pidfd >= 0) {
      pollfd fd{pidfd, POLLIN, 0};
      poll(&fd, 1, static_cast<int>(left.count()));
    } else {
      poll(nullptr, 0, static_cast<int>(std::min<int64_t>(left.count(), 5)));
    }
  }
  if (pidfd >= 0) close(pidfd);
  return status_;
}

std::string DescribeWaitStatus(int status) {
  auto signal_name = [](int signo) {
    const char* abbrev = sigabbrev_np(signo);
    return abbrev != nullptr ? "SIG" + std::string(abbrev) : "signal " + std::to_string(signo);
  };
  if (WIFEXITED(status)) return "exited with code " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status)) {
    return "killed by " + signal_name(WTERMSIG(status)) +
           (WCOREDUMP(status) ? " (core dumped)" : "");
  }
  if (WIFSTOPPED(status)) return "stopped by " + signal_name(WSTOPSIG(status));
  return "wait status " + std::to_string(status);
}

}  // namespace avc::launch
