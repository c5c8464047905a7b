// `avc bench chaos` in short, as CI runs it: an undisturbed scan in the simulated cell (every
// driver and a recorder separate processes), then the same scan with `avc scan` SIGKILLed halfway
// and resumed, and with the robot driver SIGKILLed and restarted, then two cells with different
// ids scanning at once on the same multicast groups. Each must hold every image exactly once and
// end with the undisturbed scan's kept images and mesh, byte for byte.

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "bench/chaos/chaos_compare.h"
#include "bench/chaos/chaos_scan.h"
#include "bench/devices/scan_process.h"
#include "core/bus/bus_options.h"
#include "core/launch/child_process.h"
#include "core/util/sha256.h"
#include "tests/bench/short_scan.h"
#include "tests/support/test_support.h"

namespace avc::bench {
namespace {

namespace fs = std::filesystem;

class ChaosMultiproc : public ::testing::Test {
 protected:
  void SetUp() override {
    WriteNominalCalibration(dir_ / "calibration.yaml", testing::kShortScanWidth,
                            testing::kShortScanHeight);
  }

  // The short scan of cell `cell` on the test's bus.
  ChaosScanOptions Scan(const std::string& name, const std::string& cell,
                        const std::optional<ChaosFault>& fault) const {
    bus::BusOptions bus = bus::ResolveBusOptions({}, "chaos-test");
    bus.cell = cell;
    ChaosScanOptions options = testing::ShortScan(dir_.path(), name, bus);
    options.fault = fault;
    // A surfacer configured away from its defaults: a restarted one and `avc replay` (from the
    // CONFIG in the log) must surface with the same options.
    options.cell.service_args["avc-surfacer"] = {"--set", "surface.final_smoothing.iterations=1"};
    return options;
  }

  testing::TempDir dir_{"avc-chaos"};
};

std::string Explain(const ChaosComparison& comparison, const ChaosScanResult& result) {
  return fmt::format("{}\n{}", fmt::join(comparison.problems, "\n"), result.error);
}

TEST_F(ChaosMultiproc, KilledScansAndConcurrentCellsEndAsTheUndisturbedScan) {
  const ChaosScanResult reference = RunChaosScan(Scan("reference", "cell-a", std::nullopt));
  ASSERT_TRUE(reference.error.empty()) << reference.error;
  const ChaosComparison itself = CompareWithReference(reference, reference);
  ASSERT_TRUE(itself.ok()) << Explain(itself, reference);
  EXPECT_GE(reference.kept.size(), 10u);
  EXPECT_GT(reference.mesh_bytes, 1000u);
  EXPECT_EQ(reference.recordings, 1u);
  std::printf("[ measured ] reference: %zu captures, %.1f s\n", reference.captures,
              reference.wall_s);

  // Its recording alone rebuilds the same mesh and cameras, byte for byte (`avc replay`).
  std::vector<fs::path> logs;
  for (const auto& entry : fs::directory_iterator(dir_ / "reference" / "cell" / "recordings")) {
    logs.push_back(entry.path());
  }
  ASSERT_EQ(logs.size(), 1u);
  const fs::path replayed = dir_ / "replayed";
  launch::ChildProcess replay =
      launch::ChildProcess::Spawn({{testing::Executable("avc").string(), "replay", logs[0].string(),
                                    "--nodes", "scan", "--output", replayed.string()},
                                   {},
                                   "",
                                   (dir_ / "replay.log").string()});
  const std::optional<int> replay_status = replay.WaitFor(std::chrono::milliseconds(180000));
  ASSERT_TRUE(replay_status.has_value() && WIFEXITED(*replay_status) &&
              WEXITSTATUS(*replay_status) == 0)
      << testing::ReadFile(dir_ / "replay.log");
  EXPECT_EQ(Sha256Hex(testing::ReadFile(replayed / "scan" / "model" / "mesh.ply")),
            reference.mesh_sha256)
      << testing::ReadFile(dir_ / "replay.log");
  EXPECT_EQ(Sha256Hex(testing::ReadFile(replayed / "scan" / "cameras.json")),
            reference.cameras_sha256);

  // `avc scan` killed outright halfway is resumed; the robot driver killed early is restarted.
  const std::vector<ChaosFault> faults = {{"avc-scan", 0.4 * reference.wall_s},
                                          {"avc-robot", 0.25 * reference.wall_s}};
  for (const ChaosFault& fault : faults) {
    const ChaosScanResult run = RunChaosScan(Scan("kill-" + fault.victim, "cell-a", fault));
    const ChaosComparison comparison = CompareWithReference(reference, run);
    EXPECT_TRUE(comparison.ok()) << fault.victim << ": " << Explain(comparison, run);
    EXPECT_TRUE(run.fault_injected) << fault.victim;
    EXPECT_TRUE(comparison.mesh_identical) << fault.victim;
    EXPECT_TRUE(comparison.lost.empty() && comparison.duplicated.empty()) << fault.victim;
    if (fault.victim == "avc-scan") {
      EXPECT_GE(run.resumes, 1);
    } else {
      EXPECT_EQ(run.restarts, 1);
    }
    std::printf("[ measured ] %s killed at %.1f s: %d resumes, %.1f s\n", fault.victim.c_str(),
                run.killed_at_s, run.resumes, run.wall_s);
  }

  // Two cells on one network, told apart by their ids only: neither renders a frame for the
  // other (frames == captures) and both end as the scan run alone.
  const std::vector<ChaosScanResult> cells = RunConcurrentChaosScans(
      {Scan("cell-a", "cell-a", std::nullopt), Scan("cell-b", "cell-b", std::nullopt)});
  for (const ChaosScanResult& cell : cells) {
    const ChaosComparison comparison = CompareWithReference(reference, cell);
    EXPECT_TRUE(comparison.ok()) << cell.cell << ": " << Explain(comparison, cell);
    EXPECT_EQ(cell.truth_frames, cell.captures) << cell.cell;
    std::printf("[ measured ] %s concurrent: %.1f s\n", cell.cell.c_str(), cell.wall_s);
  }
}

}  // namespace
}  // namespace avc::bench
