#pragma once

// One scan in its own simulated cell (every driver and a recorder as separate processes, plus an
// `avc scan` child), disturbed by at most one crash: a SIGKILL of one process at a chosen moment.
// A killed cell process is started again, as `avc up` would; a killed or faulted scan is resumed
// with `avc scan --resume`, until the scan is done. What the scan directory then holds is
// summarised so runs can be compared with an undisturbed one (chaos_compare.h).

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "bench/devices/cell_processes.h"

namespace avc::bench {

// The processes a chaos run may kill.
const std::vector<std::string>& ChaosVictims();

struct ChaosFault {
  std::string victim;  // one of ChaosVictims()
  double at_s = 0;     // seconds after the scan first started
};

struct ChaosScanOptions {
  std::string label;               // names the run in progress lines and errors
  CellProcessOptions cell;         // work_dir holds the cell's logs; a recorder is always added
  std::filesystem::path scan_dir;  // must not hold a scan yet
  std::filesystem::path calibration;
  std::vector<std::string> planner_args;  // empty: ScanProcessOptions' default
  std::optional<ChaosFault> fault;
  int max_runs = 6;        // scan starts, the first one included
  double timeout_s = 900;  // for the whole scan, resumes included
};

struct ChaosScanResult {
  std::string label, cell;
  std::string error;  // empty when the scan finished (DONE); else what failed, with log tails
  std::optional<ChaosFault> fault;  // the one asked for
  bool fault_injected = false;      // false when the scan ended before its moment
  double killed_at_s = 0;
  int resumes = 0;   // `avc scan --resume` runs
  int restarts = 0;  // cell processes started again
  size_t captures = 0;
  size_t image_files = 0;             // files under scan_dir/images
  size_t truth_frames = 0;            // frames the simulator rendered (truth.jsonl)
  std::vector<std::string> captured;  // "<image id> <sha256>" of every capture, in record order
  std::vector<std::string> kept;      // the same for the views kept after pruning
  std::vector<std::string> record_problems;  // missing or altered image files
  size_t mesh_bytes = 0;
  std::string mesh_sha256;
  std::string cameras_sha256;  // cameras.json, to tell poses from meshing when meshes differ
  size_t recordings = 0;       // .lcmlog files the recorder wrote
  double wall_s = 0;           // first scan start to the scan's end
};

// Runs the scan; never throws (a failure is in .error).
ChaosScanResult RunChaosScan(const ChaosScanOptions& options);

// Runs the scans at the same time, each on its own thread (its processes live as long as it).
std::vector<ChaosScanResult> RunConcurrentChaosScans(const std::vector<ChaosScanOptions>& scans);

}  // namespace avc::bench
