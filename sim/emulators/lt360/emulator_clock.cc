#include "sim/emulators/lt360/emulator_clock.h"

#include "core/util/clock.h"

namespace avc::sim {

RealTimeEmulatorClock::RealTimeEmulatorClock() : start_us_(MonotonicMicros()) {}

double RealTimeEmulatorClock::NowSeconds() { return (MonotonicMicros() - start_us_) * 1e-6; }

double SteppedEmulatorClock::NowSeconds() {
  double now = now_s_.load();
  while (!now_s_.compare_exchange_weak(now, now + step_s_)) {
  }
  return now;
}

void SteppedEmulatorClock::Advance(double seconds) {
  double now = now_s_.load();
  while (!now_s_.compare_exchange_weak(now, now + seconds)) {
  }
}

}  // namespace avc::sim
