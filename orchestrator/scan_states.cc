#include "orchestrator/scan_states.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <stdexcept>

namespace avc::orchestrator {
namespace {

using S = ScanState;

constexpr int kStateCount = static_cast<int>(S::kAborted) + 1;

const std::string kRobot = "avc-robot";
const std::string kTurntable = "avc-turntable";
const std::string kCamera = "avc-camera";
const std::string kBuilder = "avc-builder";
const std::string kClusterer = "avc-clusterer";
const std::string kSurfacer = "avc-surfacer";
const std::string kPlanner = "avc-planner";

std::vector<StateRow> BuildTable() {
  // The planning and processing states are jobs for the stage services over the bus (plan jobs,
  // scan_stage_jobs.h).
  const std::vector<std::string> cell = {kRobot, kTurntable, kCamera};
  const std::vector<std::string> planning = {kRobot, kTurntable, kCamera, kPlanner};
  // Rows in enum order, columns aligned by hand. `next` holds each state's own successors; the
  // edges all working states share (interruptions, resume) are added below from the `working`
  // column, so they are stated once.
  // clang-format off
  std::vector<StateRow> rows = {
    // state, name, working, main-line step, services READY first, own next states; description
    {S::kIdle,            "IDLE",             false,  0, {},            {S::kCheckDevices},
     "nothing running; a new scan or a persisted one about to resume"},
    {S::kCheckDevices,    "CHECK_DEVICES",    true,   1, cell,          {S::kCalibrate,
                                                                         S::kLoadCalibration},
     "robot, turntable and camera READY; the arm powered, its brakes released"},
    {S::kCalibrate,       "CALIBRATE",        true,   2, cell,          {S::kFrame},
     "collect board views and solve intrinsics, hand-eye and axis"},
    {S::kLoadCalibration, "LOAD_CALIBRATION", true,   2, {},            {S::kFrame},
     "load calibration.yaml made earlier; the scan keeps its copy"},
    {S::kFrame,           "FRAME",            true,   3, planning,      {S::kInitialCapture},
     "frame the plant from live views at the first height"},
    {S::kInitialCapture,  "INITIAL_CAPTURE",  true,   4, planning,      {S::kActiveVision},
     "the 3x10 orbit (each height framed first); carve the plant proxy"},
    {S::kActiveVision,    "ACTIVE_VISION",    true,   5, planning,      {S::kPruneViews},
     "score the proxy's surface patches; capture next-best views"},
    {S::kPruneViews,      "PRUNE_VIEWS",      true,   6, {kPlanner},    {S::kBuild},
     "drop redundant views"},
    {S::kBuild,           "BUILD",            true,   7, {kBuilder},    {S::kMergeCluster},
     "masks, plant proxy and multi-view stereo from the kept views"},
    {S::kMergeCluster,    "MERGE_CLUSTER",    true,   8, {kClusterer},  {S::kSurface},
     "merge points into the proxy and cluster them"},
    {S::kSurface,         "SURFACE",          true,   9, {kSurfacer},   {S::kTraits},
     "triangulate the clusters into one mesh"},
    {S::kTraits,          "TRAITS",           true,  10, {},            {S::kReport},
     "measure area, height and leaf angles from the mesh"},
    {S::kReport,          "REPORT",           true,  11, {},            {S::kDone},
     "write the report and close the scan directory"},
    {S::kDone,            "DONE",             false, 12, {},            {},
     "finished; every product is in the scan directory"},
    {S::kPaused,          "PAUSED",           false, -1, {},            {},
     "stopped on request; resumes where it was"},
    {S::kFault,           "FAULT",            false, -1, {},            {},
     "stopped by an error; resumes where it was once fixed"},
    {S::kAborted,         "ABORTED",          false, -1, {},            {},
     "given up; the scan directory keeps what was made"},
  };
  // clang-format on
  std::vector<S> working;
  for (const StateRow& row : rows) {
    if (row.working) working.push_back(row.state);
  }
  for (StateRow& row : rows) {
    if (row.working) {
      row.next.insert(row.next.end(), {S::kPaused, S::kFault, S::kAborted});
    } else if (row.state == S::kIdle || row.state == S::kPaused || row.state == S::kFault) {
      // IDLE starts a persisted scan at its persisted state; PAUSED and FAULT resume the
      // interrupted one (ScanStateMachine checks which).
      for (S to : working) {
        if (std::find(row.next.begin(), row.next.end(), to) == row.next.end()) {
          row.next.push_back(to);
        }
      }
      row.next.push_back(S::kAborted);
    }
  }
  return rows;
}

const std::vector<StateRow>& Table() {
  static const std::vector<StateRow> table = BuildTable();
  return table;
}

std::string JoinNames(const std::vector<S>& states) {
  std::string text;
  for (S state : states) {
    if (!text.empty()) text += ", ";
    text += StateName(state);
  }
  return text;
}

// The NEXT column: the twelve working states shortened to one phrase where all of them are
// allowed (IDLE, PAUSED, FAULT), so the table fits a terminal.
std::string NextColumn(const StateRow& row) {
  if (row.next.empty()) return "- (terminal)";
  for (const StateRow& candidate : Table()) {
    if (candidate.working &&
        std::find(row.next.begin(), row.next.end(), candidate.state) == row.next.end()) {
      return JoinNames(row.next);
    }
  }
  std::string text = "any working state";
  for (S next : row.next) {
    if (!IsWorkingState(next)) text += fmt::format(", {}", StateName(next));
  }
  return text;
}

}  // namespace

std::span<const StateRow> StateTable() { return Table(); }

const StateRow& Row(ScanState state) {
  const int index = static_cast<int>(state);
  if (index < 0 || index >= kStateCount) {
    throw std::invalid_argument(fmt::format("not a scan state: {}", index));
  }
  return Table()[static_cast<size_t>(index)];
}

std::string_view StateName(ScanState state) { return Row(state).name; }

std::optional<ScanState> ParseScanState(std::string_view name) {
  for (const StateRow& row : Table()) {
    if (row.name == name) return row.state;
  }
  return std::nullopt;
}

bool IsAllowed(ScanState from, ScanState to) {
  const std::vector<S>& next = Row(from).next;
  return std::find(next.begin(), next.end(), to) != next.end();
}

const std::vector<ScanState>& NextStates(ScanState state) { return Row(state).next; }
const std::vector<std::string>& RequiredServices(ScanState state) { return Row(state).services; }
bool IsWorkingState(ScanState state) { return Row(state).working; }
bool IsTerminal(ScanState state) { return Row(state).next.empty(); }

const std::vector<ScanState>& MainLine() {
  static const std::vector<S> line = [] {
    std::vector<const StateRow*> rows;
    for (const StateRow& row : Table()) {
      if (row.step >= 0) rows.push_back(&row);
    }
    std::stable_sort(rows.begin(), rows.end(),
                     [](const StateRow* a, const StateRow* b) { return a->step < b->step; });
    std::vector<S> states;
    for (const StateRow* row : rows) states.push_back(row->state);
    return states;
  }();
  return line;
}

double MainLineFraction(ScanState state) {
  const int step = Row(state).step;
  if (step < 0) {
    throw std::invalid_argument(fmt::format("{} is not on the main line", StateName(state)));
  }
  return static_cast<double>(step) / Row(MainLine().back()).step;
}

std::string FormatStateTable() {
  struct Line {
    std::string state, services, next, description;
  };
  std::vector<Line> lines = {{"STATE", "REQUIRES READY", "NEXT", "WHAT HAPPENS"}};
  for (const StateRow& row : Table()) {
    std::string services;
    for (const std::string& service : row.services) {
      if (!services.empty()) services += ", ";
      services += service;
    }
    lines.push_back({std::string(row.name), services.empty() ? "-" : services, NextColumn(row),
                     std::string(row.description)});
  }
  size_t state_width = 0, services_width = 0, next_width = 0;
  for (const Line& line : lines) {
    state_width = std::max(state_width, line.state.size());
    services_width = std::max(services_width, line.services.size());
    next_width = std::max(next_width, line.next.size());
  }
  std::string text;
  for (const Line& line : lines) {
    text += fmt::format("{:<{}}  {:<{}}  {:<{}}  {}\n", line.state, state_width, line.services,
                        services_width, line.next, next_width, line.description);
  }
  return text;
}

ScanStateMachine ScanStateMachine::Restore(ScanState state, std::optional<ScanState> interrupted) {
  const bool interruption = state == S::kPaused || state == S::kFault;
  if (interruption && !interrupted) {
    throw std::invalid_argument(
        fmt::format("{} needs the working state it interrupted", StateName(state)));
  }
  if (!interruption && interrupted) {
    throw std::invalid_argument(fmt::format("{} cannot have an interrupted state ({} given)",
                                            StateName(state), StateName(*interrupted)));
  }
  if (interrupted && !IsWorkingState(*interrupted)) {
    throw std::invalid_argument(fmt::format("{} is not a working state, so {} cannot interrupt it",
                                            StateName(*interrupted), StateName(state)));
  }
  ScanStateMachine machine;
  machine.state_ = state;
  machine.interrupted_ = interrupted;
  return machine;
}

std::string ScanStateMachine::TryTransition(ScanState to, int64_t utime, std::string detail) {
  if (!IsAllowed(state_, to)) {
    if (IsTerminal(state_)) {
      return fmt::format("{} -> {} is not allowed; {} is terminal", StateName(state_),
                         StateName(to), StateName(state_));
    }
    return fmt::format("{} -> {} is not allowed; from {}: {}", StateName(state_), StateName(to),
                       StateName(state_), JoinNames(NextStates(state_)));
  }
  if (interrupted_ && IsWorkingState(to) && to != *interrupted_) {
    return fmt::format("{} -> {} is not allowed; {} interrupted {}, so resume goes to {}",
                       StateName(state_), StateName(to), StateName(state_),
                       StateName(*interrupted_), StateName(*interrupted_));
  }
  if ((to == S::kPaused || to == S::kFault) && IsWorkingState(state_)) {
    interrupted_ = state_;
  } else {
    interrupted_.reset();
  }
  history_.push_back({state_, to, utime, std::move(detail)});
  state_ = to;
  return "";
}

}  // namespace avc::orchestrator
