#include "sim/emulators/clock/emulator_clock.h"

#include <fmt/format.h>

#include <chrono>
#include <stdexcept>
#include <thread>

#include "core/util/clock.h"

namespace avc::sim {

ScaledEmulatorClock::ScaledEmulatorClock(double scale)
    : scale_(scale), start_us_(MonotonicMicros()) {
  if (!(scale > 0 && scale <= 1000)) {
    throw std::invalid_argument(fmt::format("clock scale {} is outside (0, 1000]", scale));
  }
}

double ScaledEmulatorClock::NowSeconds() { return (MonotonicMicros() - start_us_) * 1e-6 * scale_; }

void ScaledEmulatorClock::SleepUntil(double simulated_s) {
  const double remaining_real_s = (simulated_s - NowSeconds()) / scale_;
  if (remaining_real_s > 0) {
    std::this_thread::sleep_for(std::chrono::duration<double>(remaining_real_s));
  }
}

double SteppedEmulatorClock::NowSeconds() {
  double now = now_s_.load();
  while (!now_s_.compare_exchange_weak(now, now + step_s_)) {
  }
  return now;
}

void SteppedEmulatorClock::SleepUntil(double simulated_s) {
  double now = now_s_.load();
  while (now < simulated_s && !now_s_.compare_exchange_weak(now, simulated_s)) {
  }
}

void SteppedEmulatorClock::Advance(double seconds) {
  double now = now_s_.load();
  while (!now_s_.compare_exchange_weak(now, now + seconds)) {
  }
}

}  // namespace avc::sim
