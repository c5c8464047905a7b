#include "drivers/turntable/turntable_controller.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace avc::turntable {
namespace {

double Deg(int tenths) { return tenths / 10.0; }

}  // namespace

int AngularDistanceTenths(int a, int b) {
  int d = NormaliseTenths(b - a);
  if (d > 1800) d -= 3600;
  return d;
}

const char* MoveKindName(MoveKind kind) {
  switch (kind) {
    case MoveKind::kGoto:
      return "goto";
    case MoveKind::kStep:
      return "step";
    case MoveKind::kHome:
      return "home";
  }
  return "move";
}

std::string ControllerOptions::Validate() const {
  if (!(default_speed_deg_s > 0)) return "default turntable speed must be > 0 deg/s";
  if (!(duration_margin >= 1) || !(duration_slack_s >= 0)) {
    return "move duration margin must be >= 1 and slack >= 0";
  }
  if (!(stall_timeout_s > 0)) return "stall timeout must be > 0 s";
  if (tolerance_tenths < 0) return "tolerance must be >= 0";
  return "";
}

TurntableController::TurntableController(Lt360Device& device, ControllerOptions options,
                                         const Clock& clock)
    : device_(device), options_(options), clock_(clock) {
  const std::string problem = options_.Validate();
  if (!problem.empty()) throw std::invalid_argument(problem);
}

std::optional<int> TurntableController::target_tenths() const {
  if (!move_) return std::nullopt;
  return move_->target_tenths;
}

void TurntableController::ApplySpeed(double speed_deg_s) {
  const double speed = speed_deg_s > 0 ? speed_deg_s : options_.default_speed_deg_s;
  if (!std::isfinite(speed)) throw std::invalid_argument("turntable speed must be finite");
  // Only when it changes, and only if the table has a speed command at all.
  if (speed != current_speed_ && device_.options().table.Supports(CommandKind::kSetSpeed)) {
    device_.SetSpeed(speed);
  }
  current_speed_ = speed;
}

void TurntableController::Begin(MoveKind kind, int target_tenths, int distance_tenths) {
  const int64_t now = clock_.NowMicros();
  const double expected_s = std::abs(distance_tenths) / 10.0 / current_speed_;
  move_ = Move{kind,
               NormaliseTenths(target_tenths),
               now,
               expected_s * options_.duration_margin + options_.duration_slack_s,
               reading_.position_tenths,
               now};
}

void TurntableController::StartGoto(int target_tenths, Direction direction, double speed_deg_s) {
  if (move_) throw std::logic_error("a turntable move is already running");
  ApplySpeed(speed_deg_s);
  const int start = device_.PositionTenths();
  reading_.position_tenths = start;
  const int target = NormaliseTenths(target_tenths);
  int distance = AngularDistanceTenths(start, target);
  // Angles grow counter-clockwise seen from above: CW travel is negative.
  if (direction == Direction::kCw && distance > 0) distance -= 3600;
  if (direction == Direction::kCcw && distance < 0) distance += 3600;
  device_.Goto(target, direction);
  Begin(MoveKind::kGoto, target, distance);
}

void TurntableController::StartStep(int delta_tenths, double speed_deg_s) {
  if (move_) throw std::logic_error("a turntable move is already running");
  ApplySpeed(speed_deg_s);
  const int start = device_.PositionTenths();
  reading_.position_tenths = start;
  device_.Step(delta_tenths);
  Begin(MoveKind::kStep, start + delta_tenths, delta_tenths);
}

void TurntableController::StartHome(double speed_deg_s) {
  if (move_) throw std::logic_error("a turntable move is already running");
  ApplySpeed(speed_deg_s);
  const int start = device_.PositionTenths();
  reading_.position_tenths = start;
  homed_ = false;
  device_.Home();
  Begin(MoveKind::kHome, 0, AngularDistanceTenths(start, 0));
}

bool TurntableController::Stop() {
  device_.Stop();
  const bool had_move = move_.has_value();
  move_.reset();
  return had_move;
}

MoveReport TurntableController::Finish(MoveResult result, std::string detail) {
  if (result == MoveResult::kDone && move_->kind == MoveKind::kHome) homed_ = true;
  move_.reset();
  return {result, std::move(detail)};
}

MoveReport TurntableController::Poll() {
  reading_.position_tenths = device_.PositionTenths();
  reading_.motion = device_.Moving();
  if (!move_) return {};
  const int64_t now = clock_.NowMicros();
  const int position = reading_.position_tenths;
  const int error = AngularDistanceTenths(position, move_->target_tenths);
  if (reading_.motion == Motion::kNone && std::abs(error) <= options_.tolerance_tenths) {
    return Finish(MoveResult::kDone,
                  fmt::format("{} reached {:.1f} deg", MoveKindName(move_->kind), Deg(position)));
  }
  if (position != move_->last_position) {
    move_->last_position = position;
    move_->last_progress_us = now;
  }
  const double still_s = (now - move_->last_progress_us) * 1e-6;
  const double elapsed_s = (now - move_->started_us) * 1e-6;
  std::string failure;
  if (still_s >= options_.stall_timeout_s) {
    failure = fmt::format(
        "turntable stalled at {:.1f} deg (target {:.1f} deg, motion {}): no progress for {:.1f} s",
        Deg(position), Deg(move_->target_tenths), MotionName(reading_.motion), still_s);
  } else if (elapsed_s > move_->allowed_s) {
    failure = fmt::format("{} to {:.1f} deg took longer than {:.1f} s (at {:.1f} deg)",
                          MoveKindName(move_->kind), Deg(move_->target_tenths), move_->allowed_s,
                          Deg(position));
  }
  if (failure.empty()) return {};
  // Do not leave a table turning that we have given up on.
  try {
    device_.Stop();
  } catch (const std::exception& e) {
    failure += fmt::format("; stopping it failed too: {}", e.what());
  }
  return Finish(MoveResult::kFailed, failure);
}

}  // namespace avc::turntable
