#pragma once

// One child process in its own process group: started with fork/exec, signalled as a group,
// reaped without blocking. Exec failures reach the parent as exceptions, not as a silent exit 127.

#include <sys/types.h>

#include <chrono>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace avc::launch {

struct SpawnSpec {
  std::vector<std::string> argv;           // argv[0] is looked up in PATH if it has no '/'
  std::map<std::string, std::string> env;  // added to (overriding) the current environment
  std::string working_dir;                 // empty = current
  std::string log_file;                    // stdout+stderr appended here; empty = inherit
};

class ChildProcess {
 public:
  // Starts the process. Its stdin is /dev/null (it runs in a background process group, where
  // reading a terminal would stop it); it gets SIGTERM when the thread that spawned it ends
  // (PR_SET_PDEATHSIG), so call this from the thread that lives as long as the child should.
  // Throws std::runtime_error naming argv[0] and the errno text when it cannot start.
  static ChildProcess Spawn(const SpawnSpec& spec);

  ChildProcess(ChildProcess&& other) noexcept;
  ChildProcess& operator=(ChildProcess&& other) noexcept;
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;
  // If still running: SIGKILL the group and reap.
  ~ChildProcess();

  pid_t pid() const { return pid_; }
  // True until the child has exited (zombies count as exited).
  bool running() const;
  // Sends signo to the child's process group. False once the child has been reaped.
  bool Signal(int signo);
  // The raw wait status once the child has exited, without blocking; cached after.
  std::optional<int> TryWait();
  // Waits up to timeout for the child to exit.
  std::optional<int> WaitFor(std::chrono::milliseconds timeout);

 private:
  explicit ChildProcess(pid_t pid) : pid_(pid) {}
  void KillAndReap();

  pid_t pid_ = 0;  // 0 when moved from
  std::optional<int> status_;
};

// "exited with code 3", "killed by SIGKILL".
std::string DescribeWaitStatus(int status);

}  // namespace avc::launch
