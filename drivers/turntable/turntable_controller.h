#pragma once

// The turntable's move state machine on top of Lt360Device, without any bus: start a move, then
// Poll() (about 10 Hz) reads position and motion and decides when the move is done (stopped
// within tolerance of the target) or failed (no progress for the stall time, or longer than the
// expected duration allows). Times come from an injected clock so tests control them.

#include <optional>
#include <string>

#include "core/util/clock.h"
#include "drivers/turntable/lt360_device.h"

namespace avc::turntable {

struct ControllerOptions {
  double default_speed_deg_s = 30;
  // A move fails when it takes longer than distance / speed * margin + slack.
  double duration_margin = 1.5;
  double duration_slack_s = 5;
  // A move fails when the reported position has not changed for this long.
  double stall_timeout_s = 3;
  // Done when stopped within this of the target (the table resolves 0.1 deg).
  int tolerance_tenths = 1;

  std::string Validate() const;
};

enum class MoveKind { kGoto, kStep, kHome };
const char* MoveKindName(MoveKind kind);

enum class MoveResult { kRunning, kDone, kFailed };

struct MoveReport {
  MoveResult result = MoveResult::kRunning;
  std::string detail;  // why it failed, or where it ended
};

struct TableReading {
  int position_tenths = 0;
  Motion motion = Motion::kNone;
};

class TurntableController {
 public:
  // clock measures move durations (a monotonic clock in the service, a ManualClock in tests).
  TurntableController(Lt360Device& device, ControllerOptions options, const Clock& clock);

  // Start a move; speed_deg_s <= 0 means the default. Throws (ProtocolError, SerialTimeout,
  // SerialError, std::invalid_argument) when the device refuses or does not answer.
  void StartGoto(int target_tenths, Direction direction, double speed_deg_s);
  void StartStep(int delta_tenths, double speed_deg_s);
  void StartHome(double speed_deg_s);
  // Stops the table and forgets the running move; true if there was one.
  bool Stop();

  // Reads the device once and advances the running move. The report is kRunning while a move
  // goes on or when none is active (check move_active()). Device errors propagate.
  MoveReport Poll();

  bool move_active() const { return move_.has_value(); }
  std::optional<int> target_tenths() const;
  const TableReading& last_reading() const { return reading_; }
  bool homed() const { return homed_; }

 private:
  struct Move {
    MoveKind kind;
    int target_tenths;
    int64_t started_us;
    double allowed_s;
    int last_position;
    int64_t last_progress_us;
  };
  void ApplySpeed(double speed_deg_s);
  void Begin(MoveKind kind, int target_tenths, int distance_tenths);
  MoveReport Finish(MoveResult result, std::string detail);

  Lt360Device& device_;
  ControllerOptions options_;
  const Clock& clock_;
  std::optional<Move> move_;
  TableReading reading_;
  double current_speed_ = 0;
  bool homed_ = false;
};

// Shortest signed distance from a to b in tenths, in (-1800, 1800].
int AngularDistanceTenths(int a, int b);

}  // namespace avc::turntable
