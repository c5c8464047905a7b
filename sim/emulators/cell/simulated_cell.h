#pragma once

// The whole simulated cell in one process (`avc sim cell`): the UR5 emulator (RTDE, primary,
// secondary, dashboard), the LT360 emulator on a pseudo-terminal and the PTP/IP camera, all on
// one shared clock. The camera renders the plant from the TRUE camera pose at the moment of each
// capture: the arm's true joints through the true DH set and hand-eye, the table's true angle
// about its true axis (sim::CameraAt). The real drivers talk to it exactly as to hardware.

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "core/camera/camera_io.h"
#include "sim/cell/cell_truth.h"
#include "sim/cell/noise.h"
#include "sim/emulators/clock/emulator_clock.h"
#include "sim/emulators/lt360/lt360_emulator.h"
#include "sim/emulators/ptpip/ptpip_camera.h"
#include "sim/emulators/ur5/ur5_emulator.h"
#include "sim/render/render_options.h"
#include "sim/render/renderer.h"
#include "sim/scene/scene.h"

namespace avc::sim {

struct SimulatedCellOptions {
  CellTruth cell = NominalCell();
  Scene scene;
  double time_scale = 1;        // simulated seconds per real second for every emulator
  ur5::Ur5EmulatorOptions arm;  // .cell is replaced by `cell`
  Lt360EmulatorOptions table;   // speed, acceleration, angle error model
  PtpIpCameraOptions camera;    // port, capture latency (.frame_source is the renderer)
  RenderOptions render;
  bool png = false;       // store frames as PNG (lossless) instead of JPEG
  int jpeg_quality = 95;  // 1..100
  bool noise = false;     // exposure and pixel noise, seeded per frame
  uint64_t noise_seed = 1;
  // When set: a symlink <link_dir>/lt360 to the table's pty (a stable name for launch files) and
  // <link_dir>/truth.jsonl, one line appended per captured frame with its true camera.
  std::filesystem::path link_dir;

  std::string Validate() const;
};

class SimulatedCell {
 public:
  // Starts every emulator. Throws std::invalid_argument for bad options and std::runtime_error
  // when a port or pty cannot be had.
  explicit SimulatedCell(SimulatedCellOptions options);
  ~SimulatedCell();
  SimulatedCell(const SimulatedCell&) = delete;
  SimulatedCell& operator=(const SimulatedCell&) = delete;

  ur5::Ur5Emulator& arm() { return *arm_; }
  Lt360Emulator& table() { return *table_; }
  PtpIpCamera& camera() { return *camera_; }
  EmulatorClock& clock() { return *clock_; }
  const CellTruth& truth() const { return options_.cell; }

  // The pty path drivers open: the symlink when link_dir is set, else the pty itself.
  std::string turntable_device() const;
  // "ptpip:127.0.0.1:PORT"
  std::string camera_port() const;
  // One line per interface, for the terminal and the log.
  std::string Describe() const;

  // The camera the next capture would render from (true pose at this instant).
  camera::Camera TrueCameraNow();
  int64_t frames_rendered() const;

 private:
  EmulatedFrame RenderFrame();

  SimulatedCellOptions options_;
  std::shared_ptr<ScaledEmulatorClock> clock_;
  std::unique_ptr<ur5::Ur5Emulator> arm_;
  std::unique_ptr<Lt360Emulator> table_;
  std::filesystem::path table_link_;

  mutable std::mutex render_mutex_;  // the camera thread renders; tests may ask for poses
  Renderer renderer_;
  int64_t frames_rendered_ = 0;
  std::ofstream truth_log_;

  std::unique_ptr<PtpIpCamera> camera_;  // last: its thread calls RenderFrame
};

// The frames a simulated cell logged to truth.jsonl, in capture order, each named by the camera's
// file name. Throws std::runtime_error naming the file and line of a bad entry.
std::vector<camera::NamedCamera> ReadTruthLog(const std::filesystem::path& path);

}  // namespace avc::sim
