#pragma once

// A scan's persisted state: scan.json in the scan directory. It is rewritten atomically after every
// step, so a scan resumes after any process died without recapturing the images it already has:
// the record says where the scan was and which image files (by sha256) it holds. The camera of each
// image lives in cameras.json, not here.

#include <array>
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "orchestrator/scan_states.h"

namespace avc::orchestrator {

struct CaptureRecord {
  int index = 0;
  std::string image_id;            // "view_0003"
  std::string file;                // relative to the scan dir: "images/view_0003.png"
  std::string sha256;              // hex of the file bytes
  std::array<double, 6> joints{};  // rad
  double table_angle = 0;          // rad
  // What the controller and the turntable reported once the view was reached: the camera is
  // placed from these (as the calibrator does), not from the commands.
  std::array<double, 16> reported_T_base_flange{};  // row-major 4x4, metres
  double reported_table_angle = 0;                  // rad
  std::string phase;   // "frame", "initial", "active"; "" until planned
  std::string reason;  // why this view was taken
  bool kept = true;    // false once PRUNE_VIEWS drops it

  bool operator==(const CaptureRecord&) const = default;
};

struct PhaseTiming {
  std::string state;  // a state name
  int64_t start_utime = 0;
  int64_t end_utime = 0;  // 0 while running

  bool operator==(const PhaseTiming&) const = default;
};

struct ScanRecord {
  static constexpr int kFormatVersion = 1;

  std::string scan_id;
  std::string cell;
  int64_t created_utime = 0;
  ScanState state = ScanState::kIdle;
  std::optional<ScanState> interrupted;  // set in PAUSED and FAULT
  std::string detail;
  std::string fault;
  std::vector<PhaseTiming> phases;
  std::vector<CaptureRecord> captures;
  nlohmann::json options = nlohmann::json::object();  // the scan's configuration in force

  // The capture with this index, or nullptr.
  const CaptureRecord* CaptureFor(int index) const;
  // Opens a phase for state at utime, closing a still-running one first at the same time.
  void StartPhase(ScanState state, int64_t utime);
  // Closes the running phase, if any.
  void EndPhase(int64_t utime);

  bool operator==(const ScanRecord&) const = default;
};

// Writes scan_dir/scan.json atomically (temp file, fsync, rename, fsync of the directory) with
// keys in a fixed order, so the same record gives the same bytes. Throws std::runtime_error naming
// the path and the system's reason; the previous scan.json is then left as it was.
void SaveScanRecord(const ScanRecord& record, const std::filesystem::path& scan_dir);

// Reads scan_dir/scan.json. Throws std::runtime_error naming the file and the bad field.
ScanRecord LoadScanRecord(const std::filesystem::path& scan_dir);

// One sentence per capture whose file is missing or no longer matches its sha256: the images a
// resume must capture again. Empty when every file is intact.
std::vector<std::string> VerifyCaptures(const ScanRecord& record,
                                        const std::filesystem::path& scan_dir);

}  // namespace avc::orchestrator
