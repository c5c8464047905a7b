#include "core/bus/event_loop.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/eventfd.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

#include "core/util/log.h"

namespace avc::bus {
namespace {

// Self-pipe shared by the signal handler and the loop that owns signals.
int g_signal_pipe[2] = {-1, -1};
std::atomic<bool> g_signals_owned{false};

extern "C" void WriteSignalToPipe(int signo) {
  const int saved_errno = errno;
  const unsigned char byte = static_cast<unsigned char>(signo);
  // A full pipe only loses a repeated signal; the loop already has one to act on.
  [[maybe_unused]] ssize_t n = write(g_signal_pipe[1], &byte, 1);
  errno = saved_errno;
}

void SetNonBlockingCloexec(int fd) {
  fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) | O_NONBLOCK);
  fcntl(fd, F_SETFD, fcntl(fd, F_GETFD) | FD_CLOEXEC);
}

}  // namespace

EventLoop::EventLoop() {
  wake_fd_ = eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
  if (wake_fd_ < 0) throw std::runtime_error(std::string("eventfd: ") + std::strerror(errno));
}

EventLoop::~EventLoop() {
  if (owns_signals_) {
    // Restore default dispositions so a later signal is not written into a dead pipe.
    for (int signo : handled_signals_) signal(signo, SIG_DFL);
    close(g_signal_pipe[0]);
    close(g_signal_pipe[1]);
    g_signal_pipe[0] = g_signal_pipe[1] = -1;
    g_signals_owned = false;
  }
  close(wake_fd_);
}

void EventLoop::WatchFd(int fd, Callback on_readable) {
  UnwatchFd(fd);
  fds_.emplace_back(fd, std::move(on_readable));
}

void EventLoop::UnwatchFd(int fd) {
  std::erase_if(fds_, [fd](const auto& entry) { return entry.first == fd; });
}

EventLoop::TimerId EventLoop::AddTimer(Duration delay, Callback fn, bool repeating) {
  if (repeating && delay < std::chrono::milliseconds(1)) {
    throw std::invalid_argument("EventLoop::AddTimer: a repeating timer needs a period >= 1 ms");
  }
  const TimerId id = next_timer_id_++;
  const Deadline deadline = std::chrono::steady_clock::now() + delay;
  timers_.emplace(std::make_pair(deadline, id), Timer{delay, repeating, std::move(fn)});
  timer_deadlines_.emplace(id, deadline);
  return id;
}

void EventLoop::CancelTimer(TimerId id) {
  auto it = timer_deadlines_.find(id);
  if (it == timer_deadlines_.end()) return;
  timers_.erase(std::make_pair(it->second, id));
  timer_deadlines_.erase(it);
}

void EventLoop::Post(Callback fn) {
  {
    std::lock_guard lock(posted_mutex_);
    posted_.push_back(std::move(fn));
  }
  Wake();
}

void EventLoop::OnSignals(const std::vector<int>& signals, std::function<void(int)> on_signal) {
  if (!owns_signals_) {
    if (g_signals_owned.exchange(true)) {
      throw std::logic_error("EventLoop::OnSignals: another event loop already owns signals");
    }
    if (pipe(g_signal_pipe) != 0) {
      throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
    }
    SetNonBlockingCloexec(g_signal_pipe[0]);
    SetNonBlockingCloexec(g_signal_pipe[1]);
    owns_signals_ = true;
    WatchFd(g_signal_pipe[0], [this] { DrainSignalPipe(); });
  }
  on_signal_ = std::move(on_signal);
  struct sigaction action {};
  action.sa_handler = WriteSignalToPipe;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  for (int signo : signals) {
    sigaction(signo, &action, nullptr);
    handled_signals_.push_back(signo);
  }
}

void EventLoop::QuitOnTerminationSignals(std::function<void(int)> on_signal) {
  OnSignals({SIGINT, SIGTERM}, [this, on_signal = std::move(on_signal)](int signo) {
    termination_signal_ = signo;
    if (on_signal) on_signal(signo);
    Quit(0);
  });
}

int EventLoop::Run() {
  while (RunOnce(std::chrono::hours(1))) {
  }
  return exit_code_;
}

bool EventLoop::RunOnce(Duration max_wait) {
  RunPosted();
  RunDueTimers();
  if (quitting()) return false;

  auto wait = max_wait;
  if (!timers_.empty()) {
    const auto until_timer = std::chrono::duration_cast<Duration>(timers_.begin()->first.first -
                                                                  std::chrono::steady_clock::now());
    wait = std::clamp(until_timer, Duration::zero(), max_wait);
  }
  std::vector<pollfd> polled;
  polled.reserve(fds_.size() + 1);
  polled.push_back(pollfd{wake_fd_, POLLIN, 0});
  for (const auto& [fd, callback] : fds_) polled.push_back(pollfd{fd, POLLIN, 0});
  // Round up so a timer due in 0.4 ms does not spin with a zero timeout.
  const int timeout_ms = static_cast<int>((wait.count() + 999) / 1000);
  const int ready = poll(polled.data(), polled.size(), timeout_ms);
  if (ready < 0 && errno != EINTR) {
    log::Error("event loop: poll failed: {}", std::strerror(errno));
  }
  if (ready > 0) {
    if (polled[0].revents & POLLIN) DrainWakePipe();
    for (size_t i = 1; i < polled.size(); ++i) {
      if (!(polled[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      // Look the callback up again: an earlier callback may have unwatched this fd.
      const int fd = polled[i].fd;
      auto it = std::find_if(fds_.begin(), fds_.end(),
                             [fd](const auto& entry) { return entry.first == fd; });
      if (it == fds_.end()) continue;
      Callback callback = it->second;  // copy: the callback may unwatch itself
      callback();
    }
  }
  RunPosted();
  RunDueTimers();
  return !quitting();
}

bool EventLoop::RunUntil(const std::function<bool()>& done, Duration timeout) {
  const auto end = std::chrono::steady_clock::now() + timeout;
  while (!done()) {
    const auto left = std::chrono::duration_cast<Duration>(end - std::chrono::steady_clock::now());
    if (left <= Duration::zero() || quitting()) return done();
    RunOnce(std::min<Duration>(left, std::chrono::milliseconds(50)));
  }
  return true;
}

void EventLoop::Quit(int exit_code) {
  {
    std::lock_guard lock(posted_mutex_);
    quit_ = true;
    exit_code_ = exit_code;
  }
  Wake();
}

bool EventLoop::quitting() const {
  std::lock_guard lock(posted_mutex_);
  return quit_;
}

void EventLoop::Wake() {
  const uint64_t one = 1;
  [[maybe_unused]] ssize_t n = write(wake_fd_, &one, sizeof(one));
}

void EventLoop::DrainWakePipe() {
  uint64_t count = 0;
  [[maybe_unused]] ssize_t n = read(wake_fd_, &count, sizeof(count));
}

void EventLoop::DrainSignalPipe() {
  unsigned char signo = 0;
  while (read(g_signal_pipe[0], &signo, 1) == 1) {
    if (on_signal_) on_signal_(signo);
  }
}

void EventLoop::RunDueTimers() {
  const auto now = std::chrono::steady_clock::now();
  while (!timers_.empty() && timers_.begin()->first.first <= now) {
    auto node = timers_.extract(timers_.begin());
    const TimerId id = node.key().second;
    Timer timer = std::move(node.mapped());
    if (timer.repeating) {
      // Schedule from the old deadline so a repeating timer keeps its rate.
      Deadline next = node.key().first + timer.period;
      if (next <= now) next = now + timer.period;
      timer_deadlines_[id] = next;
      Callback fn = timer.fn;
      timers_.emplace(std::make_pair(next, id), std::move(timer));
      fn();
    } else {
      timer_deadlines_.erase(id);
      timer.fn();
    }
  }
}

void EventLoop::RunPosted() {
  std::vector<Callback> batch;
  {
    std::lock_guard lock(posted_mutex_);
    batch.swap(posted_);
  }
  for (auto& fn : batch) fn();
}

}  // namespace avc::bus
