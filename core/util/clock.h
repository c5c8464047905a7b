#pragma once

#include <atomic>
#include <cstdint>

namespace avc {

// Time source for message headers. Live processes use the system clock; replay sets the time of
// the event being replayed, so outputs never depend on when a replay ran.
class Clock {
 public:
  virtual ~Clock() = default;
  // Microseconds since the Unix epoch.
  virtual int64_t NowMicros() const = 0;
};

class SystemClock final : public Clock {
 public:
  int64_t NowMicros() const override;
};

class ManualClock final : public Clock {
 public:
  explicit ManualClock(int64_t start_micros = 0) : now_(start_micros) {}
  int64_t NowMicros() const override { return now_.load(); }
  void Set(int64_t micros) { now_.store(micros); }
  void Advance(int64_t micros) { now_.fetch_add(micros); }

 private:
  std::atomic<int64_t> now_;
};

// Monotonic microseconds for measuring intervals (never for message contents).
int64_t MonotonicMicros();

}  // namespace avc
