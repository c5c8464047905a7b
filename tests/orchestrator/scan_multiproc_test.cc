// `avc scan` as a lab runs it, against the simulated cell and every real driver (separate
// processes on the real bus): a SIGTERM pauses the scan (exit 4, PAUSED in scan.json), a resume
// killed with SIGKILL halfway leaves a consistent scan directory, and a second resume finishes
// it (DONE): mesh, traits and report written, every image on disk exactly once and intact, and
// no view captured twice beyond the one a kill can catch between capture and record. And the
// drivers killed one after another during a scan (restarted as avc up would): resumed after any
// fault, the scan finishes the same way.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <avc/orchestrator_state_t.hpp>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bench/devices/cell_processes.h"
#include "bench/devices/scan_process.h"
#include "core/auth/command_key.h"
#include "core/bus/bus.h"
#include "core/bus/bus_options.h"
#include "core/bus/channels.h"
#include "core/bus/event_loop.h"
#include "core/launch/child_process.h"
#include "orchestrator/scan_record.h"
#include "sim/emulators/cell/simulated_cell.h"
#include "tests/support/test_support.h"

namespace avc::orchestrator {
namespace {

namespace fs = std::filesystem;
using std::chrono::milliseconds;

constexpr int kWidth = 1280, kHeight = 960;

using bench::RecordedCaptures;
using bench::WaitForCaptures;

void WriteNominalCalibration(const fs::path& path) {
  bench::WriteNominalCalibration(path, kWidth, kHeight);
}

// `avc scan ARGS...` on the test's bus with the short planner settings.
launch::ChildProcess StartScan(const std::vector<std::string>& args, const bus::BusOptions& bus,
                               const fs::path& key, const fs::path& log) {
  bench::ScanProcessOptions options;
  options.avc_binary = testing::Executable("avc");
  options.bus = bus;
  options.key_file = key;
  options.log = log;
  return bench::StartScanProcess(args, options);
}

// The nominal simulated cell with every driver, small and fast, on the test's bus.
bench::CellProcessOptions TestCell(const bus::BusOptions& bus, const fs::path& dir) {
  bench::CellProcessOptions options = bench::CellOptionsOnBus(bus, testing::Executable("avc"), dir);
  options.time_scale = 20;
  options.triangles = 8000;
  options.width = kWidth;
  options.height = kHeight;
  options.png = true;
  options.extra_sim_args = {"--nominal-cell"};
  return options;
}

// A finished scan: DONE, every image on disk once and intact, no view captured again beyond
// `extra_frames` (one per kill, caught between capture and record), the model and the report.
void ExpectFinishedScan(const fs::path& scan_dir, const bench::CellProcesses& cell,
                        size_t extra_frames) {
  const ScanRecord done = LoadScanRecord(scan_dir);
  EXPECT_EQ(done.state, ScanState::kDone);
  EXPECT_TRUE(VerifyCaptures(done, scan_dir).empty());
  size_t image_files = 0;
  for (const auto& entry : fs::directory_iterator(scan_dir / "images")) {
    image_files += entry.path().extension() == ".png";
  }
  EXPECT_EQ(image_files, done.captures.size()) << "one file per recorded capture, no strays";
  const size_t frames = sim::ReadTruthLog(cell.truth_log()).size();
  EXPECT_GE(frames, done.captures.size());
  EXPECT_LE(frames, done.captures.size() + extra_frames) << "views captured again after stops";
  int kept = 0;
  for (const CaptureRecord& capture : done.captures) {
    kept += capture.kept;
    EXPECT_FALSE(capture.phase.empty()) << capture.image_id;
  }
  EXPECT_GE(kept, 10);
  for (const char* file :
       {"calibration.yaml", "cameras.json", "colmap/images.txt", "model/ppr.bt", "model/points.ply",
        "model/clusters.ply", "model/mesh.ply", "model/traits.csv", "report.json", "report.html"}) {
    EXPECT_TRUE(fs::exists(scan_dir / file)) << file;
  }
  EXPECT_GT(fs::file_size(scan_dir / "model/mesh.ply"), 1000u);
  // avc scan's own configuration is kept beside its stages', the envelope it gave the planner in.
  const std::string configuration = testing::ReadFile(scan_dir / "config/avc-scan.toml");
  EXPECT_NE(configuration.find("[envelope]\ntable_z = "), std::string::npos) << configuration;
  // The report says what the surfacer made of the clusters.
  const nlohmann::json report = nlohmann::json::parse(testing::ReadFile(scan_dir / "report.json"));
  const nlohmann::json& surface = report.at("surface");
  EXPECT_GE(surface.at("clusters").get<int>(), 3);
  EXPECT_GE(surface.at("cells").get<int>(), surface.at("clusters").get<int>() / 2);
  EXPECT_GE(surface.at("components").get<int>(), 1);
  EXPECT_GT(surface.at("area_m2_after_phase").at("4").get<double>(), 0.001);
}

TEST(ScanMultiproc, PausedKilledAndResumedScanFinishesWithEveryImageOnce) {
  testing::TempDir dir("avc-scan-mp");
  const fs::path scan_dir = dir.path() / "plant";
  const fs::path calibration = dir.path() / "calibration.yaml";
  WriteNominalCalibration(calibration);
  const bus::BusOptions bus_options = bus::ResolveBusOptions({}, "scan-test");
  bench::CellProcesses cell(TestCell(bus_options, dir.path()));
  const fs::path log = dir.path() / "scan.log";

  {  // SIGTERM: paused, resumable.
    launch::ChildProcess scan =
        StartScan({scan_dir.string(), "--calibration", calibration.string()}, bus_options,
                  cell.key().file, log);
    ASSERT_TRUE(WaitForCaptures(scan_dir, 3, scan)) << testing::ReadFile(log) << cell.LogTails();
    scan.Signal(SIGTERM);
    const auto status = scan.WaitFor(milliseconds(30000));
    ASSERT_TRUE(status.has_value()) << "avc scan ignored SIGTERM\n" << testing::ReadFile(log);
    EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 4)
        << launch::DescribeWaitStatus(*status) << "\n"
        << testing::ReadFile(log);
    const ScanRecord paused = LoadScanRecord(scan_dir);
    EXPECT_EQ(paused.state, ScanState::kPaused);
    ASSERT_TRUE(paused.interrupted.has_value());
    EXPECT_TRUE(IsWorkingState(*paused.interrupted));
  }
  {  // A new scan in the same directory is refused: it would mix two plants.
    launch::ChildProcess again =
        StartScan({scan_dir.string(), "--calibration", calibration.string()}, bus_options,
                  cell.key().file, dir.path() / "again.log");
    const auto status = again.WaitFor(milliseconds(20000));
    ASSERT_TRUE(status.has_value());
    EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 1);
    EXPECT_NE(testing::ReadFile(dir.path() / "again.log").find("--resume"), std::string::npos);
  }
  {  // A resume with other planner settings is refused: it would plan other views.
    bench::ScanProcessOptions options;
    options.avc_binary = testing::Executable("avc");
    options.bus = bus_options;
    options.key_file = cell.key().file;
    options.log = dir.path() / "other.log";
    options.planner_args = {"--max-views", "50", "--views-per-height", "6"};
    launch::ChildProcess other = bench::StartScanProcess({"--resume", scan_dir.string()}, options);
    const auto status = other.WaitFor(milliseconds(20000));
    ASSERT_TRUE(status.has_value());
    EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 1);
    EXPECT_NE(testing::ReadFile(dir.path() / "other.log").find("max_views 14 (given 50)"),
              std::string::npos)
        << testing::ReadFile(dir.path() / "other.log");
  }
  {  // Resumed, then killed outright halfway.
    launch::ChildProcess scan =
        StartScan({"--resume", scan_dir.string()}, bus_options, cell.key().file, log);
    ASSERT_TRUE(WaitForCaptures(scan_dir, 8, scan)) << testing::ReadFile(log) << cell.LogTails();
    scan.Signal(SIGKILL);
    ASSERT_TRUE(scan.WaitFor(milliseconds(10000)).has_value());
  }
  std::vector<avc::orchestrator_state_t> states;
  {  // Resumed again: to the end, its state heard on the bus all along.
    bus::Bus bus(bus_options);
    bus::EventLoop loop;
    bus.AttachTo(loop);
    bus.Subscribe<avc::orchestrator_state_t>(channels::kOrchestratorState,
                                             [&](const avc::orchestrator_state_t& state,
                                                 const bus::RxInfo&) { states.push_back(state); });
    launch::ChildProcess scan =
        StartScan({"--resume", scan_dir.string()}, bus_options, cell.key().file, log);
    loop.RunUntil([&] { return scan.TryWait().has_value(); }, milliseconds(240000));
    const auto status = scan.WaitFor(milliseconds(1000));
    ASSERT_TRUE(status.has_value()) << "scan did not finish\n" << testing::ReadFile(log);
    ASSERT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 0)
        << launch::DescribeWaitStatus(*status) << "\n"
        << testing::ReadFile(log) << cell.LogTails();
  }

  ASSERT_FALSE(states.empty()) << "no ORCH_STATE heard";
  EXPECT_EQ(states.back().state, "DONE");
  EXPECT_EQ(states.back().scan_id, "plant");
  EXPECT_DOUBLE_EQ(states.back().fraction, 1.0);
  const auto heard = [&](const std::string& name) {
    return std::any_of(states.begin(), states.end(),
                       [&](const avc::orchestrator_state_t& s) { return s.state == name; });
  };
  EXPECT_TRUE(heard("BUILD") && heard("SURFACE") && heard("REPORT"));
  // The state goes on being published while avc-builder computes, with its own progress.
  const auto build_states =
      std::count_if(states.begin(), states.end(), [](const auto& s) { return s.state == "BUILD"; });
  EXPECT_GE(build_states, 3) << "ORCH_STATE not republished during BUILD";
  EXPECT_TRUE(std::any_of(states.begin(), states.end(), [](const avc::orchestrator_state_t& s) {
    return s.state == "BUILD" && s.detail.find("avc-builder: ") != std::string::npos;
  })) << "the builder's own progress never shown";

  ExpectFinishedScan(scan_dir, cell, 2);
  const ScanRecord done = LoadScanRecord(scan_dir);
  // The phases were timed through to the report.
  std::vector<std::string> phases;
  for (const PhaseTiming& phase : done.phases) phases.push_back(phase.state);
  EXPECT_NE(std::find(phases.begin(), phases.end(), "ACTIVE_VISION"), phases.end());
  EXPECT_EQ(phases.back(), "REPORT");
  EXPECT_TRUE(cell.Exited().empty()) << cell.LogTails();

  // One pipeline: `avc reconstruct` offline on the scan's images and cameras, with the
  // configuration its services ran with (config/), writes the bytes the stage services wrote
  // over the bus.
  const fs::path offline = dir.path() / "offline";
  launch::SpawnSpec reconstruct;
  reconstruct.argv = {testing::Executable("avc").string(),
                      "reconstruct",
                      "--dataset",
                      scan_dir.string(),
                      "--output",
                      offline.string()};
  for (const char* service : {"avc-builder", "avc-clusterer", "avc-surfacer"}) {
    const fs::path config = scan_dir / "config" / (std::string(service) + ".toml");
    ASSERT_TRUE(fs::exists(config)) << config;
    reconstruct.argv.insert(reconstruct.argv.end(), {"--config", config.string()});
  }
  reconstruct.log_file = (dir.path() / "reconstruct.log").string();
  launch::ChildProcess offline_run = launch::ChildProcess::Spawn(reconstruct);
  const auto offline_status = offline_run.WaitFor(milliseconds(240000));
  ASSERT_TRUE(offline_status && WIFEXITED(*offline_status) && WEXITSTATUS(*offline_status) == 0)
      << testing::ReadFile(dir.path() / "reconstruct.log");
  for (const char* file : {"points.ply", "ppr.bt", "clusters.ply", "mesh.ply", "traits.csv"}) {
    EXPECT_EQ(testing::ReadFile(offline / file), testing::ReadFile(scan_dir / "model" / file))
        << file << " differs between `avc reconstruct` and the scan's stage services";
  }
}

// No cell answering: the scan stops with a fault that names every missing service and says how
// to resume, and a resume tries again.
TEST(ScanMultiproc, DevicesThatNeverAnswerFaultTheScanWithTheirNames) {
  testing::TempDir dir("avc-scan-nocell");
  const fs::path scan_dir = dir.path() / "plant";
  const fs::path calibration = dir.path() / "calibration.yaml";
  WriteNominalCalibration(calibration);
  const fs::path log = dir.path() / "scan.log";
  launch::ChildProcess scan =
      StartScan({"--calibration", calibration.string(), scan_dir.string(), "--ready-timeout", "1"},
                bus::ResolveBusOptions({}, "scan-nocell-test"),
                auth::GenerateCommandKey(dir / "cell.key").file, log);
  const auto status = scan.WaitFor(milliseconds(30000));
  ASSERT_TRUE(status.has_value()) << testing::ReadFile(log);
  EXPECT_TRUE(WIFEXITED(*status) && WEXITSTATUS(*status) == 3)
      << launch::DescribeWaitStatus(*status) << "\n"
      << testing::ReadFile(log);
  const std::string said = testing::ReadFile(log);
  for (const char* service : {"avc-robot: never heard", "avc-turntable: never heard",
                              "avc-camera: never heard", "avc scan --resume"}) {
    EXPECT_NE(said.find(service), std::string::npos) << service << "\n" << said;
  }
  // Nothing was started: the record stays IDLE and a resume tries the devices again.
  EXPECT_EQ(LoadScanRecord(scan_dir).state, ScanState::kIdle);
  launch::ChildProcess again =
      StartScan({"--resume", scan_dir.string(), "--ready-timeout", "1"},
                bus::ResolveBusOptions({}, "scan-nocell-test"), dir / "cell.key", log);
  const auto again_status = again.WaitFor(milliseconds(30000));
  ASSERT_TRUE(again_status.has_value());
  EXPECT_TRUE(WIFEXITED(*again_status) && WEXITSTATUS(*again_status) == 3)
      << testing::ReadFile(log);
}

// A driver (or the simulator) that crashes during a scan is started again, as `avc up` does; the
// scan goes on or stops with a fault, and resuming it finishes the scan with every image once.
TEST(ScanMultiproc, DevicesKilledDuringTheScanAreRestartedAndTheScanFinishes) {
  testing::TempDir dir("avc-scan-kill");
  const fs::path scan_dir = dir.path() / "plant";
  const fs::path calibration = dir.path() / "calibration.yaml";
  WriteNominalCalibration(calibration);
  const bus::BusOptions bus_options = bus::ResolveBusOptions({}, "scan-kill-test");
  bench::CellProcesses cell(TestCell(bus_options, dir.path()));
  const fs::path log = dir.path() / "scan.log";
  // Which process dies after how many recorded captures (avc-planner mid-plan: the restarted
  // planner replays the views it is sent); then avc-builder while it has the scan's build job
  // (the other stages take too little time here to be caught reliably: the chaos bench kills
  // them at random).
  const std::vector<std::pair<size_t, std::string>> kills = {
      {3, "avc-robot"}, {6, "avc-camera"}, {9, "avc-turntable"}, {12, "avc-planner"}};
  const std::vector<std::pair<std::string, std::string>> stage_kills = {{"BUILD", "avc-builder"}};
  size_t next_kill = 0;
  size_t next_stage_kill = 0;
  int runs = 0;
  std::optional<int> status;
  while (runs < 6) {
    std::vector<std::string> args = {scan_dir.string()};
    args.insert(args.begin(), runs == 0 ? "--calibration" : "--resume");
    if (runs == 0) args.insert(args.begin() + 1, calibration.string());
    launch::ChildProcess scan = StartScan(args, bus_options, cell.key().file, log);
    ++runs;
    while (next_kill < kills.size() && WaitForCaptures(scan_dir, kills[next_kill].first, scan)) {
      cell.KillAndRestart(kills[next_kill].second);
      ++next_kill;
    }
    while (next_kill == kills.size() && next_stage_kill < stage_kills.size() &&
           bench::WaitForScanState(scan_dir, stage_kills[next_stage_kill].first, scan)) {
      cell.KillAndRestart(stage_kills[next_stage_kill].second);
      ++next_stage_kill;
    }
    status = scan.WaitFor(milliseconds(240000));
    ASSERT_TRUE(status.has_value()) << "scan did not finish\n" << testing::ReadFile(log);
    ASSERT_TRUE(WIFEXITED(*status)) << launch::DescribeWaitStatus(*status);
    if (WEXITSTATUS(*status) == 0) break;
    // Anything but a fault (exit 3) is a bug; a fault names what failed and is resumable.
    ASSERT_EQ(WEXITSTATUS(*status), 3) << testing::ReadFile(log) << cell.LogTails();
  }
  ASSERT_TRUE(status && WIFEXITED(*status) && WEXITSTATUS(*status) == 0)
      << "not finished after " << runs << " runs\n"
      << testing::ReadFile(log) << cell.LogTails();
  EXPECT_EQ(next_kill, kills.size()) << "the scan finished before every kill";
  EXPECT_EQ(next_stage_kill, stage_kills.size()) << "the scan finished before every stage kill";
  std::printf("[ measured ] %d scan runs for %zu device and %zu stage crashes\n", runs,
              kills.size(), stage_kills.size());
  ExpectFinishedScan(scan_dir, cell, kills.size());
  EXPECT_TRUE(cell.Exited().empty()) << cell.LogTails();
}

}  // namespace
}  // namespace avc::orchestrator
