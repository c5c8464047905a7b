#pragma once

// Where an emulator's time comes from. Every emulator of one simulated cell shares one clock so
// the arm, the table and the camera agree on "now":
//  - RealTimeEmulatorClock: wall time, for manual use and the multi-process tests;
//  - ScaledEmulatorClock: wall time times a factor, so a whole scan runs faster than real time
//    while every emulator still sees a smooth, consistent clock (avc sim cell --time-scale);
//  - SteppedEmulatorClock: advances a fixed amount every time it is read, so a move of many
//    seconds finishes in a few polls and a test runs the same every time.

#include <atomic>
#include <cstdint>

namespace avc::sim {

class EmulatorClock {
 public:
  virtual ~EmulatorClock() = default;
  // Simulated seconds since the clock started.
  virtual double NowSeconds() = 0;
  // Blocks until the clock reads at least `simulated_s` (returns at once if it already does).
  // Emulator loops pace themselves with this instead of sleeping on the wall clock.
  virtual void SleepUntil(double simulated_s) = 0;
};

class ScaledEmulatorClock : public EmulatorClock {
 public:
  // scale: simulated seconds per real second, in (0, 1000]; throws std::invalid_argument.
  explicit ScaledEmulatorClock(double scale);
  double NowSeconds() override;
  void SleepUntil(double simulated_s) override;
  double scale() const { return scale_; }

 private:
  double scale_;
  int64_t start_us_;
};

class RealTimeEmulatorClock final : public ScaledEmulatorClock {
 public:
  RealTimeEmulatorClock() : ScaledEmulatorClock(1.0) {}
};

class SteppedEmulatorClock final : public EmulatorClock {
 public:
  explicit SteppedEmulatorClock(double step_s) : step_s_(step_s) {}
  // Returns the current time, then advances it by the step.
  double NowSeconds() override;
  // Jumps the clock forward to simulated_s (never back): nothing waits in a stepped world.
  void SleepUntil(double simulated_s) override;
  // Advances without reading (a test can move time forward explicitly).
  void Advance(double seconds);

 private:
  double step_s_;
  std::atomic<double> now_s_{0};
};

}  // namespace avc::sim
