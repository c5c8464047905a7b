// The scan state machine: the table's rules, the resume check and the printed table.

#include "orchestrator/scan_states.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <stdexcept>

namespace avc::orchestrator {
namespace {

using S = ScanState;

const std::vector<S> kWorking = {S::kCheckDevices, S::kCalibrate,      S::kLoadCalibration,
                                 S::kFrame,        S::kInitialCapture, S::kActiveVision,
                                 S::kPruneViews,   S::kBuild,          S::kMergeCluster,
                                 S::kSurface,      S::kTraits,         S::kReport};

bool Contains(const std::vector<S>& states, S state) {
  return std::find(states.begin(), states.end(), state) != states.end();
}

// Walks a machine from IDLE through states, one transition each, expecting every one accepted.
void Walk(ScanStateMachine& machine, const std::vector<S>& states) {
  int64_t utime = 1000;
  for (S to : states) {
    EXPECT_EQ(machine.TryTransition(to, utime, "step"), "") << StateName(to);
    utime += 10;
  }
}

TEST(ScanStates, NamesRoundTripAndAreTheOnesPrinted) {
  const std::vector<std::string> names = {"IDLE",          "CHECK_DEVICES",
                                          "CALIBRATE",     "LOAD_CALIBRATION",
                                          "FRAME",         "INITIAL_CAPTURE",
                                          "ACTIVE_VISION", "PRUNE_VIEWS",
                                          "BUILD",         "MERGE_CLUSTER",
                                          "SURFACE",       "TRAITS",
                                          "REPORT",        "DONE",
                                          "PAUSED",        "FAULT",
                                          "ABORTED"};
  ASSERT_EQ(StateTable().size(), names.size());
  for (size_t i = 0; i < names.size(); ++i) {
    const S state = static_cast<S>(i);
    EXPECT_EQ(StateName(state), names[i]);
    EXPECT_EQ(StateTable()[i].state, state) << "table rows must be in enum order";
    ASSERT_TRUE(ParseScanState(names[i]).has_value());
    EXPECT_EQ(*ParseScanState(names[i]), state);
  }
  EXPECT_FALSE(ParseScanState("idle").has_value());
  EXPECT_FALSE(ParseScanState("").has_value());
  EXPECT_FALSE(ParseScanState("SCANNING").has_value());
}

TEST(ScanStates, MainLineIsWalkedInOrderThroughEitherCalibration) {
  const std::vector<S> expected = {S::kIdle,         S::kCheckDevices,
                                   S::kCalibrate,    S::kLoadCalibration,
                                   S::kFrame,        S::kInitialCapture,
                                   S::kActiveVision, S::kPruneViews,
                                   S::kBuild,        S::kMergeCluster,
                                   S::kSurface,      S::kTraits,
                                   S::kReport,       S::kDone};
  EXPECT_EQ(MainLine(), expected);

  for (S calibration : {S::kCalibrate, S::kLoadCalibration}) {
    std::vector<S> path;
    for (S state : MainLine()) {
      if (state == S::kIdle) continue;
      if ((state == S::kCalibrate || state == S::kLoadCalibration) && state != calibration) {
        continue;
      }
      path.push_back(state);
    }
    ScanStateMachine machine;
    Walk(machine, path);
    EXPECT_EQ(machine.state(), S::kDone);
    ASSERT_EQ(machine.history().size(), path.size());
    EXPECT_EQ(machine.history().front().from, S::kIdle);
    for (size_t i = 0; i < path.size(); ++i) {
      EXPECT_EQ(machine.history()[i].to, path[i]);
      EXPECT_EQ(machine.history()[i].utime, 1000 + 10 * static_cast<int64_t>(i));
      if (i > 0) {
        EXPECT_EQ(machine.history()[i].from, path[i - 1]);
      }
    }
    EXPECT_EQ(machine.history().back().detail, "step");
  }
}

TEST(ScanStates, IllegalJumpsAreRefusedWithTheAllowedStates) {
  ScanStateMachine machine = ScanStateMachine::Restore(S::kFrame, std::nullopt);
  EXPECT_EQ(machine.TryTransition(S::kBuild, 5, ""),
            "FRAME -> BUILD is not allowed; from FRAME: INITIAL_CAPTURE, PAUSED, FAULT, ABORTED");
  EXPECT_EQ(machine.state(), S::kFrame);
  EXPECT_TRUE(machine.history().empty());

  ScanStateMachine fresh;
  EXPECT_NE(fresh.TryTransition(S::kDone, 1, ""), "");
  EXPECT_NE(fresh.TryTransition(S::kPaused, 1, ""), "") << "nothing to pause at IDLE";
  EXPECT_EQ(fresh.state(), S::kIdle);
  // CALIBRATE goes straight to FRAME, never through LOAD_CALIBRATION.
  EXPECT_FALSE(IsAllowed(S::kCalibrate, S::kLoadCalibration));
  EXPECT_TRUE(IsAllowed(S::kCalibrate, S::kFrame));
  EXPECT_FALSE(IsAllowed(S::kBuild, S::kActiveVision)) << "no going back on the main line";
  EXPECT_FALSE(IsAllowed(S::kReport, S::kIdle));
}

TEST(ScanStates, EveryWorkingStateMayBeInterrupted) {
  for (S state : kWorking) {
    EXPECT_TRUE(IsWorkingState(state)) << StateName(state);
    for (S to : {S::kPaused, S::kFault, S::kAborted}) {
      EXPECT_TRUE(IsAllowed(state, to)) << StateName(state) << " -> " << StateName(to);
    }
  }
  for (S state : {S::kIdle, S::kDone, S::kPaused, S::kFault, S::kAborted}) {
    EXPECT_FALSE(IsWorkingState(state)) << StateName(state);
  }
  for (S from : {S::kIdle, S::kPaused, S::kFault}) {
    for (S to : kWorking) EXPECT_TRUE(IsAllowed(from, to)) << StateName(from) << StateName(to);
    EXPECT_TRUE(IsAllowed(from, S::kAborted));
    EXPECT_FALSE(IsAllowed(from, S::kDone));
  }
  EXPECT_FALSE(IsAllowed(S::kPaused, S::kFault));
  EXPECT_FALSE(IsAllowed(S::kIdle, S::kIdle));
}

TEST(ScanStates, DoneAndAbortedAreTerminal) {
  for (S state : {S::kDone, S::kAborted}) {
    EXPECT_TRUE(IsTerminal(state));
    EXPECT_TRUE(NextStates(state).empty());
    ScanStateMachine machine = ScanStateMachine::Restore(state, std::nullopt);
    for (const StateRow& row : StateTable()) {
      const std::string refusal = machine.TryTransition(row.state, 1, "");
      EXPECT_NE(refusal.find("is terminal"), std::string::npos) << refusal;
    }
    EXPECT_EQ(machine.state(), state);
  }
  for (S state : kWorking) EXPECT_FALSE(IsTerminal(state));
  EXPECT_FALSE(IsTerminal(S::kIdle));
  EXPECT_FALSE(IsTerminal(S::kPaused));
}

TEST(ScanStates, ResumeGoesBackToTheInterruptedStateOnly) {
  ScanStateMachine machine = ScanStateMachine::Restore(S::kActiveVision, std::nullopt);
  ASSERT_EQ(machine.TryTransition(S::kPaused, 10, "operator"), "");
  ASSERT_TRUE(machine.interrupted().has_value());
  EXPECT_EQ(*machine.interrupted(), S::kActiveVision);

  const std::string refusal = machine.TryTransition(S::kBuild, 20, "");
  EXPECT_NE(refusal, "");
  EXPECT_NE(refusal.find("PAUSED -> BUILD"), std::string::npos) << refusal;
  EXPECT_NE(refusal.find("resume goes to ACTIVE_VISION"), std::string::npos) << refusal;
  EXPECT_EQ(machine.state(), S::kPaused);

  EXPECT_EQ(machine.TryTransition(S::kActiveVision, 30, "resumed"), "");
  EXPECT_EQ(machine.state(), S::kActiveVision);
  EXPECT_FALSE(machine.interrupted().has_value());
  ASSERT_EQ(machine.history().size(), 2u);
  EXPECT_EQ(machine.history()[1].from, S::kPaused);
  EXPECT_EQ(machine.history()[1].detail, "resumed");

  // A fault in BUILD may be given up on.
  ScanStateMachine faulted = ScanStateMachine::Restore(S::kBuild, std::nullopt);
  ASSERT_EQ(faulted.TryTransition(S::kFault, 40, "builder died"), "");
  EXPECT_EQ(*faulted.interrupted(), S::kBuild);
  EXPECT_NE(faulted.TryTransition(S::kSurface, 50, ""), "");
  EXPECT_EQ(faulted.TryTransition(S::kAborted, 60, ""), "");
  EXPECT_FALSE(faulted.interrupted().has_value());
}

TEST(ScanStates, RestoredMachineResumesAtItsPersistedState) {
  ScanStateMachine paused = ScanStateMachine::Restore(S::kPaused, S::kMergeCluster);
  EXPECT_EQ(paused.state(), S::kPaused);
  EXPECT_NE(paused.TryTransition(S::kFrame, 1, ""), "");
  EXPECT_EQ(paused.TryTransition(S::kMergeCluster, 2, ""), "");

  // After a crash the scan starts at IDLE and goes straight to its persisted state.
  ScanStateMachine idle;
  EXPECT_EQ(idle.TryTransition(S::kSurface, 3, "resume"), "");

  EXPECT_THROW(ScanStateMachine::Restore(S::kPaused, std::nullopt), std::invalid_argument);
  EXPECT_THROW(ScanStateMachine::Restore(S::kBuild, S::kBuild), std::invalid_argument);
  EXPECT_THROW(ScanStateMachine::Restore(S::kFault, S::kDone), std::invalid_argument);
}

TEST(ScanStates, RequiredServices) {
  // The devices for the states that move or capture, with the planner where it plans; each
  // processing stage its own service.
  using V = std::vector<std::string>;
  const V cell = {"avc-robot", "avc-turntable", "avc-camera"};
  for (S state : {S::kCheckDevices, S::kCalibrate}) {
    EXPECT_EQ(RequiredServices(state), cell) << StateName(state);
  }
  const V planning = {"avc-robot", "avc-turntable", "avc-camera", "avc-planner"};
  for (S state : {S::kFrame, S::kInitialCapture, S::kActiveVision}) {
    EXPECT_EQ(RequiredServices(state), planning) << StateName(state);
  }
  EXPECT_EQ(RequiredServices(S::kPruneViews), V{"avc-planner"});
  EXPECT_EQ(RequiredServices(S::kBuild), V{"avc-builder"});
  EXPECT_EQ(RequiredServices(S::kMergeCluster), V{"avc-clusterer"});
  EXPECT_EQ(RequiredServices(S::kSurface), V{"avc-surfacer"});
  for (S state : {S::kIdle, S::kLoadCalibration, S::kTraits, S::kReport, S::kDone, S::kPaused,
                  S::kFault, S::kAborted}) {
    EXPECT_TRUE(RequiredServices(state).empty()) << StateName(state);
  }
}

TEST(ScanStates, FormattedTableListsEveryStateWithItsServicesAndNextStates) {
  const std::string table = FormatStateTable();
  std::vector<std::string> lines;
  for (size_t start = 0; start < table.size();) {
    const size_t end = table.find('\n', start);
    ASSERT_NE(end, std::string::npos) << "every line ends with a newline";
    lines.push_back(table.substr(start, end - start));
    start = end + 1;
  }
  ASSERT_EQ(lines.size(), StateTable().size() + 1) << table;
  // Columns are aligned: the second column starts at the same offset on every line.
  const size_t services_column = lines[0].find("REQUIRES READY");
  ASSERT_NE(services_column, std::string::npos);
  for (size_t i = 0; i < StateTable().size(); ++i) {
    const StateRow& row = StateTable()[i];
    const std::string& line = lines[i + 1];
    EXPECT_EQ(line.rfind(std::string(row.name) + " ", 0), 0u) << line;
    EXPECT_NE(line[services_column], ' ') << line;
    EXPECT_EQ(line[services_column - 1], ' ') << line;
    for (const std::string& service : row.services) {
      EXPECT_NE(line.find(service), std::string::npos) << line;
    }
    // IDLE, PAUSED and FAULT may go to all twelve working states, printed as one phrase.
    const bool any_working = Contains(row.next, S::kReport) && Contains(row.next, S::kFrame);
    EXPECT_EQ(any_working, line.find("any working state") != std::string::npos) << line;
    for (S next : row.next) {
      if (any_working && IsWorkingState(next)) continue;
      EXPECT_NE(line.find(StateName(next)), std::string::npos) << line;
    }
    if (row.next.empty()) {
      EXPECT_NE(line.find("terminal"), std::string::npos) << line;
    }
    EXPECT_NE(line.find(row.description), std::string::npos) << line;
  }
}

TEST(ScanStates, MainLineFractionRisesFromZeroToOne) {
  EXPECT_DOUBLE_EQ(MainLineFraction(S::kIdle), 0.0);
  EXPECT_DOUBLE_EQ(MainLineFraction(S::kDone), 1.0);
  EXPECT_DOUBLE_EQ(MainLineFraction(S::kCalibrate), MainLineFraction(S::kLoadCalibration));
  double previous = -1;
  std::set<double> distinct;
  for (S state : MainLine()) {
    const double fraction = MainLineFraction(state);
    EXPECT_GE(fraction, 0.0);
    EXPECT_LE(fraction, 1.0);
    EXPECT_GE(fraction, previous) << StateName(state);
    previous = fraction;
    distinct.insert(fraction);
  }
  EXPECT_EQ(distinct.size(), MainLine().size() - 1) << "only the two calibrations share a step";
  EXPECT_THROW(MainLineFraction(S::kPaused), std::invalid_argument);
  EXPECT_THROW(MainLineFraction(S::kAborted), std::invalid_argument);
}

TEST(ScanStates, EveryNextStateIsInTheTableOnce) {
  for (const StateRow& row : StateTable()) {
    EXPECT_FALSE(row.description.empty()) << row.name;
    std::set<S> seen;
    for (S next : row.next) {
      EXPECT_TRUE(seen.insert(next).second) << row.name << " lists " << StateName(next) << " twice";
      EXPECT_NE(next, row.state) << row.name;
    }
    EXPECT_EQ(Contains(row.next, S::kAborted), !IsTerminal(row.state)) << row.name;
  }
}

}  // namespace
}  // namespace avc::orchestrator
