#pragma once

// The calibration end to end in the simulated cell, as a lab would run it: `avc sim cell` with a
// chessboard on the turntable and the three drivers as separate processes; the calibrator
// collects its dataset over the bus and solves it; then the arm and table go through a scan
// path and each camera pose computed from the calibration (reported flange pose, commanded
// table angle) is compared with the true pose the simulator rendered from.

#include <filesystem>
#include <nlohmann/json.hpp>

namespace avc::bench {

struct CellCalibrationRunOptions {
  std::filesystem::path work_dir;
  double time_scale = 10;
  int hand_eye_poses = 12;
  int table_angles = 10;
  int scan_rings = 3;             // elevations 20..50 deg
  int scan_angles = 10;           // table angles per ring
  int samples = 4;                // render anti-aliasing (corner accuracy depends on it)
  double table_sigma_deg = 0.05;  // the emulated table's angle error per move
  int port = 7770;                // control multicast port; bulk +1
};

// Returns {"calibration": residuals, "scan": {"views", centre and rotation error medians, p90,
// max}, "acceptance": {...}}; throws std::runtime_error (with the processes' log tails) when
// the run fails.
nlohmann::json RunCellCalibration(const CellCalibrationRunOptions& options);

}  // namespace avc::bench
