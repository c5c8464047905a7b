#include "bench/chaos/chaos_scan.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <iostream>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "bench/devices/scan_process.h"
#include "core/util/file_io.h"
#include "core/util/sha256.h"
#include "orchestrator/scan_record.h"
#include "sim/emulators/cell/simulated_cell.h"

namespace avc::bench {
namespace {
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr int kScanExitFault = 3;  // `avc scan`: stopped by a fault, resumable

// One line on stderr per event; concurrent scans write whole lines.
void Progress(const std::string& label, const std::string& text) {
  static std::mutex mutex;
  std::lock_guard lock(mutex);
  std::cerr << fmt::format("[{}] {}\n", label, text);
}

std::string Describe(const std::optional<ChaosFault>& fault) {
  return fault ? fmt::format("SIGKILL {} at {:.1f} s", fault->victim, fault->at_s)
               : std::string("no fault");
}

size_t CountFiles(const fs::path& dir, const std::string& extension = "") {
  if (!fs::is_directory(dir)) return 0;
  size_t count = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    count +=
        entry.is_regular_file() && (extension.empty() || entry.path().extension() == extension);
  }
  return count;
}

std::string FileSha256(const fs::path& path) { return Sha256Hex(ReadFile(path)); }

// What the finished scan directory holds.
void Summarise(const fs::path& scan_dir, ChaosScanResult& result) {
  const orchestrator::ScanRecord record = orchestrator::LoadScanRecord(scan_dir);
  if (record.state != orchestrator::ScanState::kDone) {
    throw std::runtime_error(fmt::format("avc scan exited 0 but scan.json says {}",
                                         orchestrator::StateName(record.state)));
  }
  result.captures = record.captures.size();
  for (const orchestrator::CaptureRecord& capture : record.captures) {
    const std::string line = capture.image_id + " " + capture.sha256;
    result.captured.push_back(line);
    if (capture.kept) result.kept.push_back(line);
  }
  result.record_problems = orchestrator::VerifyCaptures(record, scan_dir);
  result.image_files = CountFiles(scan_dir / "images");
  const fs::path mesh = scan_dir / "model" / "mesh.ply";
  result.mesh_bytes = fs::file_size(mesh);
  result.mesh_sha256 = FileSha256(mesh);
  result.cameras_sha256 = FileSha256(scan_dir / "cameras.json");
}

// The scan, resumed after every kill or fault until it is done, with the fault injected on the
// way. Throws std::runtime_error saying what went wrong.
class ChaosRun {
 public:
  ChaosRun(const ChaosScanOptions& options, ChaosScanResult& result)
      : options_(options), result_(result), pending_(options.fault) {
    CellProcessOptions cell_options = options.cell;
    cell_options.record = true;
    cell_ = std::make_unique<CellProcesses>(cell_options);
    scan_.avc_binary = cell_options.avc_binary;
    scan_.bus = ClientBusOptions(cell_options, "avc-scan");
    scan_.key_file = cell_->key().file;
    scan_.log = cell_options.work_dir / "avc-scan.log";
    if (!options.planner_args.empty()) scan_.planner_args = options.planner_args;
    scan_.prefix = cell_options.cell_prefix;  // the scan runs beside the cell
  }

  void Run() {
    start_ = Clock::now();
    for (int runs = 0;; ++runs) {
      if (runs >= options_.max_runs) {
        throw std::runtime_error(fmt::format("not done after {} scan runs", runs));
      }
      // A scan killed before it wrote scan.json left nothing to resume: it starts afresh.
      const bool resume = fs::exists(options_.scan_dir / "scan.json");
      const std::vector<std::string> args =
          resume ? std::vector<std::string>{"--resume", options_.scan_dir.string()}
                 : std::vector<std::string>{options_.scan_dir.string(), "--calibration",
                                            options_.calibration.string()};
      Progress(options_.label,
               fmt::format("{:.1f} s: avc scan {}", Elapsed(), resume ? "--resume" : "started"));
      result_.resumes = runs;
      const int status = RunOnce(args);
      if (WIFEXITED(status) && WEXITSTATUS(status) == 0) break;
      const bool killed = WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL;
      const bool fault = WIFEXITED(status) && WEXITSTATUS(status) == kScanExitFault;
      if (!killed && !fault) {
        throw std::runtime_error("avc scan " + launch::DescribeWaitStatus(status));
      }
      Progress(options_.label,
               fmt::format("{:.1f} s: avc scan {}", Elapsed(), launch::DescribeWaitStatus(status)));
    }
    result_.wall_s = Elapsed();
    Progress(options_.label, fmt::format("{:.1f} s: done", result_.wall_s));
  }

  // Stops the cell (so the recorder closes its log) and counts what it left.
  void StopCell() {
    const fs::path truth = cell_->truth_log();
    const fs::path recordings = cell_->recordings_dir();
    cell_.reset();
    result_.truth_frames = sim::ReadTruthLog(truth).size();
    result_.recordings = CountFiles(recordings, ".lcmlog");
  }

  std::string LogTails() const {
    std::string tails =
        fmt::format("--- avc scan ({})\n{}", scan_.log.string(), LogTail(scan_.log, 25));
    if (cell_) tails += cell_->LogTails();
    return tails;
  }

 private:
  double Elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

  // One `avc scan` to its end; the wait status.
  int RunOnce(const std::vector<std::string>& args) {
    launch::ChildProcess scan = StartScanProcess(args, scan_);
    while (true) {
      if (const std::optional<int> status = scan.WaitFor(std::chrono::milliseconds(50))) {
        return *status;
      }
      result_.wall_s = Elapsed();
      if (result_.wall_s > options_.timeout_s) {
        throw std::runtime_error(fmt::format("timed out after {:.0f} s", options_.timeout_s));
      }
      if (pending_ && Elapsed() >= pending_->at_s) Inject(scan);
      // Only the victim dies here, and it is started again at once: any other death is a crash.
      if (const std::vector<std::string> exited = cell_->Exited(); !exited.empty()) {
        throw std::runtime_error(fmt::format("{} by itself", fmt::join(exited, ", ")));
      }
    }
  }

  void Inject(launch::ChildProcess& scan) {
    result_.fault_injected = true;
    result_.killed_at_s = Elapsed();
    Progress(options_.label,
             fmt::format("{:.1f} s: SIGKILL {}", result_.killed_at_s, pending_->victim));
    if (pending_->victim == "avc-scan") {
      scan.Signal(SIGKILL);  // resumed once it is reaped
    } else {
      cell_->KillAndRestart(pending_->victim);
      ++result_.restarts;
    }
    pending_.reset();
  }

  const ChaosScanOptions& options_;
  ChaosScanResult& result_;
  std::optional<ChaosFault> pending_;
  std::unique_ptr<CellProcesses> cell_;
  ScanProcessOptions scan_;
  Clock::time_point start_ = Clock::now();
};

}  // namespace

const std::vector<std::string>& ChaosVictims() {
  static const std::vector<std::string> victims = {
      "avc-sim",     "avc-robot",   "avc-turntable", "avc-camera",   "avc-record",
      "avc-planner", "avc-builder", "avc-clusterer", "avc-surfacer", "avc-scan"};
  return victims;
}

ChaosScanResult RunChaosScan(const ChaosScanOptions& options) {
  ChaosScanResult result;
  result.label = options.label;
  result.cell = options.cell.cell;
  result.fault = options.fault;
  std::unique_ptr<ChaosRun> run;
  try {
    if (options.fault && std::find(ChaosVictims().begin(), ChaosVictims().end(),
                                   options.fault->victim) == ChaosVictims().end()) {
      throw std::invalid_argument("no process to kill named " + options.fault->victim);
    }
    run = std::make_unique<ChaosRun>(options, result);
    run->Run();
    run->StopCell();
    Summarise(options.scan_dir, result);
  } catch (const std::exception& error) {
    result.error =
        fmt::format("{}: cell {}, {}: {}\n{}", options.label, options.cell.cell,
                    Describe(options.fault), error.what(), run ? run->LogTails() : std::string());
    Progress(options.label, fmt::format("FAILED: {}", error.what()));
  }
  return result;
}

std::vector<ChaosScanResult> RunConcurrentChaosScans(const std::vector<ChaosScanOptions>& scans) {
  std::vector<ChaosScanResult> results(scans.size());
  std::vector<std::thread> threads;
  threads.reserve(scans.size());
  for (size_t i = 0; i < scans.size(); ++i) {
    threads.emplace_back([&, i] { results[i] = RunChaosScan(scans[i]); });
  }
  for (std::thread& thread : threads) thread.join();
  return results;
}

}  // namespace avc::bench
