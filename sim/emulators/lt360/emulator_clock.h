#pragma once

// Where the emulated turntable's time comes from: real time for manual use and the multi-process
// test, or a stepped clock that advances a fixed amount every time it is read, so a move of many
// seconds finishes in a few polls and tests run faster than real time and the same every run.

#include <atomic>
#include <cstdint>

namespace avc::sim {

class EmulatorClock {
 public:
  virtual ~EmulatorClock() = default;
  virtual double NowSeconds() = 0;
};

class RealTimeEmulatorClock final : public EmulatorClock {
 public:
  RealTimeEmulatorClock();
  double NowSeconds() override;

 private:
  int64_t start_us_;
};

class SteppedEmulatorClock final : public EmulatorClock {
 public:
  explicit SteppedEmulatorClock(double step_s) : step_s_(step_s) {}
  // Returns the current time, then advances it by the step.
  double NowSeconds() override;
  // Advances without reading (a test can move time forward explicitly).
  void Advance(double seconds);

 private:
  double step_s_;
  std::atomic<double> now_s_{0};
};

}  // namespace avc::sim
