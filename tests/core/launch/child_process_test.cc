// ChildProcess (fork/exec in its own process group, signals, non-blocking reaping, exec
// failures as exceptions) and the restart Backoff.

#include "core/launch/child_process.h"

#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>

#include "core/launch/backoff.h"
#include "tests/support/test_support.h"

namespace avc::launch {
namespace {

namespace fs = std::filesystem;
using std::chrono::milliseconds;

SpawnSpec Shell(const std::string& script, const std::string& log_file = "") {
  SpawnSpec spec;
  spec.argv = {"sh", "-c", script};
  spec.log_file = log_file;
  return spec;
}

// Waits (bounded) until path contains text: the child's own signal that it got somewhere.
bool WaitForFileText(const fs::path& path, const std::string& text, milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < deadline) {
    std::error_code error;
    if (fs::exists(path, error) && testing::ReadFile(path).find(text) != std::string::npos) {
      return true;
    }
    usleep(2000);
  }
  return false;
}

// Dead: gone, or a zombie waiting for a reaper that is not us (orphans go to init, which may
// reap them late).
bool Dead(pid_t pid) {
  if (kill(pid, 0) != 0) return errno == ESRCH;
  std::error_code error;
  const fs::path stat = fs::path("/proc") / std::to_string(pid) / "stat";
  if (!fs::exists(stat, error)) return true;
  const std::string text = testing::ReadFile(stat);
  const size_t paren = text.rfind(')');
  return paren != std::string::npos && paren + 2 < text.size() && text[paren + 2] == 'Z';
}

TEST(Backoff, DoublesUpToTheCapAndResetsAfterALongRun) {
  BackoffPolicy policy;
  policy.initial = milliseconds(100);
  policy.max = milliseconds(1000);
  policy.reset_after = milliseconds(5000);
  Backoff backoff(policy);
  std::vector<int64_t> delays;
  for (int i = 0; i < 7; ++i) delays.push_back(backoff.NextDelay(milliseconds(10)).count());
  EXPECT_EQ(delays, (std::vector<int64_t>{100, 200, 400, 800, 1000, 1000, 1000}));
  // A run just short of reset_after keeps the delay at the cap.
  EXPECT_EQ(backoff.NextDelay(milliseconds(4999)), milliseconds(1000));
  // A run of reset_after or more starts over.
  EXPECT_EQ(backoff.NextDelay(milliseconds(5000)), milliseconds(100));
  EXPECT_EQ(backoff.NextDelay(milliseconds(0)), milliseconds(200));
  EXPECT_EQ(backoff.NextDelay(milliseconds(60'000)), milliseconds(100));
  backoff.NextDelay(milliseconds(0));
  backoff.Reset();
  EXPECT_EQ(backoff.NextDelay(milliseconds(0)), milliseconds(100));
}

TEST(Backoff, DefaultsAreTheDocumentedOnes) {
  Backoff backoff;
  std::vector<int64_t> delays;
  for (int i = 0; i < 8; ++i) delays.push_back(backoff.NextDelay(milliseconds(0)).count());
  EXPECT_EQ(delays, (std::vector<int64_t>{200, 400, 800, 1600, 3200, 6400, 10000, 10000}));
  EXPECT_EQ(backoff.NextDelay(milliseconds(10'000)), milliseconds(200));
}

TEST(Backoff, AnInitialAboveTheCapIsCapped) {
  BackoffPolicy policy;
  policy.initial = milliseconds(300);
  policy.max = milliseconds(500);
  Backoff backoff(policy);
  EXPECT_EQ(backoff.NextDelay(milliseconds(0)), milliseconds(300));
  EXPECT_EQ(backoff.NextDelay(milliseconds(0)), milliseconds(500));
  EXPECT_EQ(backoff.NextDelay(milliseconds(0)), milliseconds(500));
}

TEST(ChildProcess, ExitCodeIsReported) {
  ChildProcess child = ChildProcess::Spawn(Shell("exit 3"));
  EXPECT_GT(child.pid(), 0);
  const std::optional<int> status = child.WaitFor(milliseconds(5000));
  ASSERT_TRUE(status.has_value());
  EXPECT_TRUE(WIFEXITED(*status));
  EXPECT_EQ(WEXITSTATUS(*status), 3);
  EXPECT_EQ(DescribeWaitStatus(*status), "exited with code 3");
  EXPECT_FALSE(child.running());
  EXPECT_EQ(child.TryWait(), status) << "the status is cached once reaped";
  EXPECT_FALSE(child.Signal(SIGTERM)) << "a reaped child cannot be signalled";
}

TEST(ChildProcess, SignalReachesTheWholeGroup) {
  testing::TempDir dir("avc-child");
  const fs::path log = dir / "out.log";
  // The shell starts a grandchild in its group, then says so.
  ChildProcess child =
      ChildProcess::Spawn(Shell("sleep 30 & echo \"grandchild $!\"; wait", log.string()));
  EXPECT_TRUE(child.running());
  EXPECT_FALSE(child.TryWait().has_value());
  ASSERT_TRUE(WaitForFileText(log, "grandchild ", milliseconds(5000)));
  const std::string text = testing::ReadFile(log);
  const pid_t grandchild = std::stoi(text.substr(text.find("grandchild ") + 11));
  EXPECT_EQ(getpgid(child.pid()), child.pid()) << "the child leads its own process group";
  EXPECT_EQ(getpgid(grandchild), child.pid());

  EXPECT_TRUE(child.Signal(SIGTERM));
  const std::optional<int> status = child.WaitFor(milliseconds(5000));
  ASSERT_TRUE(status.has_value());
  EXPECT_TRUE(WIFSIGNALED(*status));
  EXPECT_EQ(DescribeWaitStatus(*status), "killed by SIGTERM");
  // The grandchild (reaped by init, not us) got the signal too.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (!Dead(grandchild) && std::chrono::steady_clock::now() < deadline) usleep(2000);
  EXPECT_TRUE(Dead(grandchild)) << "grandchild " << grandchild << " still alive";
}

// A descriptor the parent opened without O_CLOEXEC (as another thread's library might) must not
// stay open in a running child: it would hold the parent's pipe or port for the child's life.
TEST(ChildProcess, DescriptorsWithoutCloseOnExecAreNotInherited) {
  int ends[2];
  ASSERT_EQ(pipe(ends), 0) << "a pipe without O_CLOEXEC";
  ChildProcess child = ChildProcess::Spawn(Shell("exec sleep 30"));
  close(ends[1]);
  pollfd reader{ends[0], POLLIN, 0};
  const int ready = poll(&reader, 1, 5000);
  close(ends[0]);
  EXPECT_EQ(ready, 1) << "the write end is still open somewhere: the child inherited it";
  EXPECT_TRUE(reader.revents & POLLHUP);
  EXPECT_TRUE(child.running()) << "the check must be made while the child runs";
}

TEST(ChildProcess, DescribeWaitStatusNamesSignals) {
  ChildProcess child = ChildProcess::Spawn(Shell("exec sleep 30"));
  EXPECT_TRUE(child.Signal(SIGKILL));
  const std::optional<int> status = child.WaitFor(milliseconds(5000));
  ASSERT_TRUE(status.has_value());
  EXPECT_EQ(DescribeWaitStatus(*status), "killed by SIGKILL");
  EXPECT_EQ(DescribeWaitStatus(0), "exited with code 0");
}

TEST(ChildProcess, WaitForTimesOutOnARunningChild) {
  ChildProcess child = ChildProcess::Spawn(Shell("exec sleep 30"));
  const auto start = std::chrono::steady_clock::now();
  EXPECT_FALSE(child.WaitFor(milliseconds(100)).has_value());
  const auto waited = std::chrono::steady_clock::now() - start;
  EXPECT_GE(waited, milliseconds(95));
  EXPECT_LT(waited, milliseconds(3000));
  EXPECT_TRUE(child.running());
}

TEST(ChildProcess, DestructorKillsAndReaps) {
  pid_t pid = 0;
  {
    ChildProcess child = ChildProcess::Spawn(Shell("exec sleep 30"));
    pid = child.pid();
    ASSERT_EQ(kill(pid, 0), 0);
  }
  errno = 0;
  EXPECT_EQ(kill(pid, 0), -1);
  EXPECT_EQ(errno, ESRCH) << "the child must be killed and reaped, not left a zombie";
}

TEST(ChildProcess, MovedFromObjectOwnsNothing) {
  ChildProcess a = ChildProcess::Spawn(Shell("exit 5"));
  const pid_t pid = a.pid();
  ChildProcess b = std::move(a);
  EXPECT_EQ(a.pid(), 0);  // NOLINT(bugprone-use-after-move): checking the moved-from state
  EXPECT_FALSE(a.running());
  EXPECT_EQ(b.pid(), pid);
  const std::optional<int> status = b.WaitFor(milliseconds(5000));
  ASSERT_TRUE(status.has_value());
  EXPECT_EQ(DescribeWaitStatus(*status), "exited with code 5");
}

TEST(ChildProcess, NonexistentProgramThrowsNamingIt) {
  try {
    ChildProcess::Spawn(SpawnSpec{{"avc-no-such-program-xyz", "arg"}, {}, "", ""});
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("avc-no-such-program-xyz"), std::string::npos) << what;
    EXPECT_NE(what.find("No such file or directory"), std::string::npos) << what;
  }
  // A path that does not exist fails in exec, which must also be an exception, not exit 127.
  try {
    ChildProcess::Spawn(SpawnSpec{{"/nonexistent/dir/prog"}, {}, "", ""});
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("/nonexistent/dir/prog"), std::string::npos) << what;
    EXPECT_NE(what.find("No such file or directory"), std::string::npos) << what;
  }
  EXPECT_THROW(ChildProcess::Spawn(SpawnSpec{}), std::runtime_error);
  // Nothing was left behind to reap.
  const pid_t leftover = waitpid(-1, nullptr, WNOHANG);
  const int wait_error = errno;
  EXPECT_EQ(leftover, -1);
  EXPECT_EQ(wait_error, ECHILD);
}

TEST(ChildProcess, BadWorkingDirOrLogFileThrowNamingThem) {
  SpawnSpec spec = Shell("exit 0");
  spec.working_dir = "/nonexistent/work";
  try {
    ChildProcess::Spawn(spec);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/work"), std::string::npos) << e.what();
  }
  spec = Shell("exit 0", "/nonexistent/dir/out.log");
  try {
    ChildProcess::Spawn(spec);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/out.log"), std::string::npos)
        << e.what();
  }
}

TEST(ChildProcess, LogFileGetsStdoutAndStderrAppended) {
  testing::TempDir dir("avc-child");
  const fs::path log = dir / "child.log";
  testing::WriteFile(log, "earlier line\n");
  ChildProcess child = ChildProcess::Spawn(
      Shell("echo to-stdout; echo to-stderr >&2; read line; echo \"stdin:[$line]\"", log.string()));
  // stdin is /dev/null: read finds nothing (and does not block).
  const std::optional<int> status = child.WaitFor(milliseconds(5000));
  ASSERT_TRUE(status.has_value());
  EXPECT_EQ(DescribeWaitStatus(*status), "exited with code 0");
  EXPECT_EQ(testing::ReadFile(log), "earlier line\nto-stdout\nto-stderr\nstdin:[]\n");
}

TEST(ChildProcess, EnvironmentAndWorkingDirArePassed) {
  testing::TempDir dir("avc-child");
  const fs::path log = dir / "env.log";
  setenv("AVC_TEST_INHERITED", "from-parent", 1);
  setenv("AVC_TEST_OVERRIDDEN", "parent-value", 1);
  SpawnSpec spec = Shell("echo \"$AVC_TEST_INHERITED|$AVC_TEST_OVERRIDDEN|$AVC_TEST_ADDED|$(pwd)\"",
                         log.string());
  spec.env = {{"AVC_TEST_OVERRIDDEN", "child-value"}, {"AVC_TEST_ADDED", "a b=c"}};
  spec.working_dir = dir.path().string();
  ChildProcess child = ChildProcess::Spawn(spec);
  const std::optional<int> status = child.WaitFor(milliseconds(5000));
  unsetenv("AVC_TEST_INHERITED");
  unsetenv("AVC_TEST_OVERRIDDEN");
  ASSERT_TRUE(status.has_value());
  EXPECT_EQ(DescribeWaitStatus(*status), "exited with code 0");
  EXPECT_EQ(testing::ReadFile(log),
            "from-parent|child-value|a b=c|" + fs::canonical(dir.path()).string() + "\n");
}

TEST(ChildProcess, PathInTheGivenEnvironmentIsUsedForBareNames) {
  testing::TempDir dir("avc-child");
  const fs::path tool = dir / "avc-test-tool";
  testing::WriteFile(tool, "#!/bin/sh\necho tool-ran \"$@\"\n");
  fs::permissions(tool, fs::perms::owner_all);
  const fs::path log = dir / "tool.log";
  SpawnSpec spec;
  spec.argv = {"avc-test-tool", "x"};
  spec.env = {{"PATH", dir.path().string() + ":/usr/bin:/bin"}};
  spec.log_file = log.string();
  ChildProcess child = ChildProcess::Spawn(spec);
  ASSERT_TRUE(child.WaitFor(milliseconds(5000)).has_value());
  EXPECT_EQ(testing::ReadFile(log), "tool-ran x\n");
}

}  // namespace
}  // namespace avc::launch
