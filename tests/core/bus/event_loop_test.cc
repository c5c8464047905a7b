#include "core/bus/event_loop.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <thread>

namespace avc::bus {
namespace {

using std::chrono::milliseconds;

TEST(EventLoop, RunsTimersInDeadlineOrder) {
  EventLoop loop;
  std::vector<int> order;
  loop.AddTimer(milliseconds(30), [&] { order.push_back(3); });
  loop.AddTimer(milliseconds(10), [&] { order.push_back(1); });
  loop.AddTimer(milliseconds(20), [&] { order.push_back(2); });
  EXPECT_TRUE(loop.RunUntil([&] { return order.size() == 3; }, milliseconds(2000)));
  EXPECT_EQ(order, (std::vector<int>{1, 2, 3}));
}

TEST(EventLoop, RepeatingTimerKeepsFiringUntilCancelled) {
  EventLoop loop;
  int fired = 0;
  EventLoop::TimerId id = 0;
  id = loop.AddTimer(
      milliseconds(2),
      [&] {
        if (++fired == 5) loop.CancelTimer(id);
      },
      true);
  EXPECT_TRUE(loop.RunUntil([&] { return fired == 5; }, milliseconds(2000)));
  loop.RunUntil([] { return false; }, milliseconds(20));
  EXPECT_EQ(fired, 5);
}

TEST(EventLoop, CancelledTimerNeverRuns) {
  EventLoop loop;
  bool ran = false;
  const auto id = loop.AddTimer(milliseconds(5), [&] { ran = true; });
  loop.CancelTimer(id);
  loop.RunUntil([] { return false; }, milliseconds(30));
  EXPECT_FALSE(ran);
}

TEST(EventLoop, RejectsZeroPeriodRepeatingTimer) {
  EventLoop loop;
  EXPECT_THROW(loop.AddTimer(
                   milliseconds(0), [] {}, true),
               std::invalid_argument);
}

TEST(EventLoop, PostFromAnotherThreadRunsOnLoopThread) {
  EventLoop loop;
  std::atomic<int> posted{0};
  std::thread::id ran_on;
  std::thread worker([&] {
    for (int i = 0; i < 100; ++i) {
      loop.Post([&] {
        ran_on = std::this_thread::get_id();
        ++posted;
      });
    }
  });
  EXPECT_TRUE(loop.RunUntil([&] { return posted == 100; }, milliseconds(2000)));
  worker.join();
  EXPECT_EQ(ran_on, std::this_thread::get_id());
}

TEST(EventLoop, QuitFromAnotherThreadEndsRunWithCode) {
  EventLoop loop;
  std::thread stopper([&] { loop.Quit(7); });
  EXPECT_EQ(loop.Run(), 7);
  stopper.join();
}

TEST(EventLoop, WatchedFdCallsBackWhenReadable) {
  EventLoop loop;
  int fds[2];
  ASSERT_EQ(pipe(fds), 0);
  std::string got;
  loop.WatchFd(fds[0], [&] {
    char c;
    if (read(fds[0], &c, 1) == 1) got.push_back(c);
  });
  ASSERT_EQ(write(fds[1], "ab", 2), 2);
  EXPECT_TRUE(loop.RunUntil([&] { return got == "ab"; }, milliseconds(2000)));
  loop.UnwatchFd(fds[0]);
  close(fds[0]);
  close(fds[1]);
}

TEST(EventLoop, SigtermEndsRunAfterCallback) {
  EventLoop loop;
  int seen = 0;
  loop.QuitOnTerminationSignals([&](int signo) { seen = signo; });
  loop.AddTimer(milliseconds(5), [] { kill(getpid(), SIGTERM); });
  EXPECT_EQ(loop.Run(), 0);
  EXPECT_EQ(seen, SIGTERM);
  EXPECT_EQ(loop.termination_signal(), SIGTERM);
}

TEST(EventLoop, OnlyOneLoopOwnsSignals) {
  EventLoop first;
  first.QuitOnTerminationSignals();
  EventLoop second;
  EXPECT_THROW(second.QuitOnTerminationSignals(), std::logic_error);
}

}  // namespace
}  // namespace avc::bus
