#include "sim/emulators/ur5/trapezoid_profile.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace avc::sim::ur5 {

TrapezoidProfile::TrapezoidProfile(double distance, double max_velocity, double acceleration)
    : distance_(distance), acceleration_(acceleration) {
  if (!(distance >= 0) || !std::isfinite(distance) || !(max_velocity > 0) ||
      !std::isfinite(max_velocity) || !(acceleration > 0) || !std::isfinite(acceleration)) {
    throw std::invalid_argument(fmt::format(
        "trapezoid profile: distance {} must be >= 0, velocity {} and acceleration {} > 0",
        distance, max_velocity, acceleration));
  }
  // Reaching max_velocity and stopping again takes v^2/a of distance.
  if (max_velocity * max_velocity / acceleration <= distance) {
    peak_velocity_ = max_velocity;
    accel_time_ = max_velocity / acceleration;
    cruise_time_ = (distance - max_velocity * accel_time_) / max_velocity;
  } else {
    accel_time_ = std::sqrt(distance / acceleration);
    peak_velocity_ = acceleration * accel_time_;
    cruise_time_ = 0;
  }
}

double TrapezoidProfile::Position(double t) const {
  t = std::clamp(t, 0.0, duration());
  const double accel_distance = 0.5 * acceleration_ * accel_time_ * accel_time_;
  if (t <= accel_time_) return 0.5 * acceleration_ * t * t;
  if (t <= accel_time_ + cruise_time_) {
    return accel_distance + peak_velocity_ * (t - accel_time_);
  }
  const double remaining = duration() - t;
  return distance_ - 0.5 * acceleration_ * remaining * remaining;
}

double TrapezoidProfile::Velocity(double t) const {
  if (t <= 0 || t >= duration()) return 0;
  if (t <= accel_time_) return acceleration_ * t;
  if (t <= accel_time_ + cruise_time_) return peak_velocity_;
  return acceleration_ * (duration() - t);
}

}  // namespace avc::sim::ur5
