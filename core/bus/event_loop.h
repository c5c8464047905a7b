#pragma once

// A single-threaded event loop: file descriptors, timers, work posted from other threads, and
// POSIX signals delivered through a self-pipe. Everything registered runs on the thread that
// calls Run(), so node state needs no locks and LCM's one-thread handle() rule holds by
// construction.

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <utility>
#include <vector>

namespace avc::bus {

class EventLoop {
 public:
  using Callback = std::function<void()>;
  using Duration = std::chrono::microseconds;
  using TimerId = uint64_t;

  EventLoop();
  ~EventLoop();
  EventLoop(const EventLoop&) = delete;
  EventLoop& operator=(const EventLoop&) = delete;

  // on_readable runs on the loop thread whenever fd is readable.
  void WatchFd(int fd, Callback on_readable);
  void UnwatchFd(int fd);

  // Runs fn after delay (and every delay after that when repeating). Returns an id for
  // CancelTimer. Loop thread only.
  TimerId AddTimer(Duration delay, Callback fn, bool repeating = false);
  void CancelTimer(TimerId id);

  // Runs fn on the loop thread soon. Safe from any thread.
  void Post(Callback fn);

  // Routes the given signals to on_signal on the loop thread. One loop per process owns signals.
  void OnSignals(const std::vector<int>& signals, std::function<void(int)> on_signal);
  // SIGINT/SIGTERM end Run() cleanly; on_signal (optional) runs first, e.g. to flush files.
  void QuitOnTerminationSignals(std::function<void(int)> on_signal = {});

  // Runs until Quit(); returns the code given to Quit().
  int Run();
  // Waits up to max_wait for one round of events and handles them. Returns false once quitting.
  bool RunOnce(Duration max_wait);
  // Runs until done() is true (checked after every round) or timeout passes; returns done().
  bool RunUntil(const std::function<bool()>& done, Duration timeout);
  // Makes Run() return. Safe from any thread.
  void Quit(int exit_code = 0);
  bool quitting() const;
  // The last termination signal received, 0 if none.
  int termination_signal() const { return termination_signal_; }

 private:
  struct Timer {
    Duration period;
    bool repeating;
    Callback fn;
  };
  using Deadline = std::chrono::steady_clock::time_point;

  void Wake();
  void DrainWakePipe();
  void DrainSignalPipe();
  void RunDueTimers();
  void RunPosted();

  int wake_fd_ = -1;  // eventfd: Post() and Quit() wake poll()
  std::vector<std::pair<int, Callback>> fds_;
  std::map<std::pair<Deadline, TimerId>, Timer> timers_;
  std::map<TimerId, Deadline> timer_deadlines_;
  TimerId next_timer_id_ = 1;

  mutable std::mutex posted_mutex_;
  std::vector<Callback> posted_;
  bool quit_ = false;
  int exit_code_ = 0;

  std::function<void(int)> on_signal_;
  bool owns_signals_ = false;
  std::vector<int> handled_signals_;  // restored to SIG_DFL on destruction
  int termination_signal_ = 0;
};

}  // namespace avc::bus
