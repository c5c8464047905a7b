#pragma once

// `avc scan` as a child process against a cell of CellProcesses, and what its scan directory
// holds so far: shared by the scan tests and `avc bench chaos`, which kill and resume scans.

#include <chrono>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "core/bus/bus_options.h"
#include "core/launch/child_process.h"
#include "sim/cell/cell_fixtures.h"

namespace avc::bench {

struct ScanProcessOptions {
  std::filesystem::path avc_binary;  // the `avc` executable
  bus::BusOptions bus;               // the cell's URLs and id
  std::filesystem::path key_file;    // the cell's motion-command key
  std::filesystem::path log;         // stdout and stderr appended here
  // A short scan: the 3 x 6 orbit's first views and a few next-best ones.
  std::vector<std::string> planner_args = {"--max-views", "14", "--views-per-height", "6"};
  // The fixed envelope the cell's avc-robot enforces (CellProcesses), for the planner.
  std::vector<std::string> envelope_args = sim::RobotEnvelopeArguments(sim::NominalCellEnvelope());
  // Put before `avc scan` (CellProcessOptions::cell_prefix).
  std::vector<std::string> prefix;
};

// Starts `avc scan ARGS...` on the options' bus, with its planner arguments and key.
launch::ChildProcess StartScanProcess(const std::vector<std::string>& args,
                                      const ScanProcessOptions& options);

// The calibration a perfect `avc calibrate` would give in the nominal simulated cell at this
// image size.
void WriteNominalCalibration(const std::filesystem::path& path, int width, int height);

// How many captures scan_dir/scan.json records; 0 while it is not written yet.
size_t RecordedCaptures(const std::filesystem::path& scan_dir);

// Polls scan.json (written atomically) until it records `count` captures. False when the scan
// ended first or the timeout passed.
bool WaitForCaptures(const std::filesystem::path& scan_dir, size_t count,
                     launch::ChildProcess& scan,
                     std::chrono::milliseconds timeout = std::chrono::milliseconds(120000));

// Polls scan.json until the scan is in `state` (a state name, e.g. "BUILD"). False when the scan
// ended first or the timeout passed.
bool WaitForScanState(const std::filesystem::path& scan_dir, const std::string& state,
                      launch::ChildProcess& scan,
                      std::chrono::milliseconds timeout = std::chrono::milliseconds(120000));

}  // namespace avc::bench
