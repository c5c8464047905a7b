#pragma once

// The simulated cell `avc demo` runs on, as a lab would run a real one: `avc up` on a launch file
// written into the work folder, starting `avc sim cell` (with the arguments given), the three
// drivers and optionally a recorder. Its processes talk on the bus options given (passed as
// AVC_LCM_URL, AVC_BULK_URL and AVC_CELL). The drivers obey only commands signed with the
// cell's own key, work_dir/cell.key (made at the first start). The destructor stops them all
// (SIGTERM to `avc up`, which stops its children).

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/auth/command_key.h"
#include "core/bus/bus_options.h"
#include "core/calibration/cell/cell_calibration.h"
#include "core/launch/child_process.h"
#include "sim/dataset/render_dataset.h"

namespace avc::cli {

struct DemoCellOptions {
  std::filesystem::path avc_binary;   // the `avc` executable
  std::filesystem::path work_dir;     // launch file, logs, the emulator's pty link
  std::vector<std::string> sim_args;  // after `avc sim cell`, e.g. {"--plant", "broadleaf"}
  // after `avc robot --host ... --key ...`, e.g. the envelope (sim::RobotEnvelopeArguments)
  std::vector<std::string> robot_args;
  std::filesystem::path record_to;  // an LCM log of everything on the bus; empty: none
  bus::BusOptions bus;
};

// The launch file's text (TOML), for the options above and the drivers' key file.
std::string DemoLaunchFile(const DemoCellOptions& options, const std::filesystem::path& key_file);

class DemoCell {
 public:
  // Writes work_dir/launch.toml and starts `avc up` on it (logs in work_dir/logs). Throws
  // std::runtime_error when it cannot start.
  explicit DemoCell(const DemoCellOptions& options);
  ~DemoCell();
  DemoCell(const DemoCell&) = delete;
  DemoCell& operator=(const DemoCell&) = delete;

  // The tail of `avc up`'s log, for error messages.
  std::string LogTail(int lines = 20) const;
  // The key the drivers check motion commands with: give it to the CellClient.
  const auth::CommandKey& key() const { return key_; }

 private:
  std::filesystem::path log_;
  auth::CommandKey key_;
  std::optional<launch::ChildProcess> up_;
};

// The simulated plant's mesh (with its organ labels) in the frame of a calibration made over the
// simulator's default chessboard: the two worlds meet at the board both know. Written as
// gt_mesh.ply into a scan, it lets the builder and `avc eval` score the scan against the truth.
void WriteGroundTruthMesh(const sim::RenderDatasetOptions& scene,
                          const calibration::CellCalibration& calibration,
                          const std::filesystem::path& path);

}  // namespace avc::cli
