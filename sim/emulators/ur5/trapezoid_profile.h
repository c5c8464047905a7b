#pragma once

// One-dimensional trapezoidal velocity profile from rest to rest: accelerate at `acceleration`,
// cruise at `max_velocity`, decelerate; a triangle when the distance is too short to reach the
// cruise speed. The controller's movej/movel time-law.

namespace avc::sim::ur5 {

class TrapezoidProfile {
 public:
  TrapezoidProfile() = default;
  // Throws std::invalid_argument for a negative distance or non-positive rates.
  TrapezoidProfile(double distance, double max_velocity, double acceleration);

  double duration() const { return 2 * accel_time_ + cruise_time_; }
  double distance() const { return distance_; }
  // Position and velocity at time t, clamped to [0, duration()].
  double Position(double t) const;
  double Velocity(double t) const;

 private:
  double distance_ = 0;
  double acceleration_ = 1;
  double peak_velocity_ = 0;
  double accel_time_ = 0;
  double cruise_time_ = 0;
};

}  // namespace avc::sim::ur5
