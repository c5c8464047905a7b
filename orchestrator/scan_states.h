#pragma once

// The scan's explicit state machine, as data. One table (StateTable) says, per state, what happens
// in it, which services must report READY before it starts and where it may go next; every rule
// below reads that table. The machine takes time as an argument (no clock inside), so a replayed
// scan makes the same history.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace avc::orchestrator {

enum class ScanState {
  kIdle,
  kCheckDevices,
  kCalibrate,
  kLoadCalibration,
  kFrame,
  kInitialCapture,
  kActiveVision,
  kPruneViews,
  kBuild,
  kMergeCluster,
  kSurface,
  kTraits,
  kReport,
  kDone,
  kPaused,
  kFault,
  kAborted,
};

// One row of the table.
struct StateRow {
  ScanState state;
  std::string_view name;  // as printed and persisted: "ACTIVE_VISION"
  bool working;           // does scan work: may be paused, faulted, aborted and resumed to
  int step;               // place on the main line (0 = IDLE), -1 off it
  // Services (as heartbeats name them) that must report READY before the state starts.
  std::vector<std::string> services;
  std::vector<ScanState> next;   // allowed next states; empty for terminal states
  std::string_view description;  // one line: what happens in this state
};

// Every state, in enum order.
std::span<const StateRow> StateTable();
const StateRow& Row(ScanState state);

std::string_view StateName(ScanState state);
std::optional<ScanState> ParseScanState(std::string_view name);

bool IsAllowed(ScanState from, ScanState to);
const std::vector<ScanState>& NextStates(ScanState state);
const std::vector<std::string>& RequiredServices(ScanState state);
bool IsWorkingState(ScanState state);
bool IsTerminal(ScanState state);

// IDLE to DONE in order. CALIBRATE and LOAD_CALIBRATION are alternatives at the same step; both
// are listed, CALIBRATE first.
const std::vector<ScanState>& MainLine();
// The step of a main-line state as a fraction of the line, 0 (IDLE) to 1 (DONE), for progress.
// Throws std::invalid_argument for PAUSED, FAULT and ABORTED (use the interrupted state).
double MainLineFraction(ScanState state);

// The table for `--states`: state, required services, next states, description; aligned columns.
std::string FormatStateTable();

struct Transition {
  ScanState from;
  ScanState to;
  int64_t utime;
  std::string detail;
};

class ScanStateMachine {
 public:
  // A new scan, at IDLE.
  ScanStateMachine() = default;
  // A persisted scan restored for resume: at state, interrupted from `interrupted` when state is
  // PAUSED or FAULT. Throws std::invalid_argument for an inconsistent pair (an interrupted state
  // that is not a working state, or one given for a state other than PAUSED/FAULT).
  static ScanStateMachine Restore(ScanState state, std::optional<ScanState> interrupted);

  // "" when the transition is made, else a sentence saying why it is refused (nothing changes).
  std::string TryTransition(ScanState to, int64_t utime, std::string detail);

  ScanState state() const { return state_; }
  // The working state PAUSED or FAULT interrupted; empty in any other state.
  std::optional<ScanState> interrupted() const { return interrupted_; }
  const std::vector<Transition>& history() const { return history_; }

 private:
  ScanState state_ = ScanState::kIdle;
  std::optional<ScanState> interrupted_;
  std::vector<Transition> history_;
};

}  // namespace avc::orchestrator
