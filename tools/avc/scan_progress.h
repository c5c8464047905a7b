#pragma once

// What `avc scan` and `avc demo` show of a scan: the progress line (phase, images, elapsed, ETA;
// rewritten in place on a terminal, one line per event in a log) and the closing message with
// the exit code.

#include <optional>
#include <string>
#include <vector>

#include "core/bus/background_heartbeat.h"
#include "core/bus/bus.h"
#include "core/bus/event_loop.h"
#include "core/camera/camera_io.h"
#include "orchestrator/scan_run.h"

namespace avc::cli {

void ShowScanProgress(const orchestrator::ScanProgress& progress);

// Shows each progress event and publishes the scan's state (orchestrator_state_t on ORCH_STATE)
// on every change and again every second while the loop runs (the scan runs the loop whenever
// it waits on the cell or on a stage service, so all through the reconstruction; not while the
// planner computes a next view). The scan is the cell's
// orchestrator: it also beats as "avc-orchestrator" ten times a second from a thread of its
// own (so planning and reconstruction are not silence), which arms the robot driver's
// watchdog: when the scan dies or loses the network while the arm moves, the arm is stopped
// within 500 ms.
class ScanStateBroadcast {
 public:
  ScanStateBroadcast(bus::Bus& bus, bus::EventLoop& loop);
  ~ScanStateBroadcast();
  ScanStateBroadcast(const ScanStateBroadcast&) = delete;
  ScanStateBroadcast& operator=(const ScanStateBroadcast&) = delete;

  void operator()(const orchestrator::ScanProgress& progress);
  // Publishes the kept views' cameras (scan_cameras_t on SCAN_CAMERAS) for the log: with the
  // image products they are what `avc replay` rebuilds the model from. For
  // ScanRunOptions::on_kept_cameras.
  void PublishKeptCameras(const std::string& scan_id,
                          const std::vector<camera::NamedCamera>& cameras);

 private:
  void Publish();

  bus::Bus& bus_;
  bus::EventLoop& loop_;
  bus::EventLoop::TimerId timer_;
  bus::BackgroundHeartbeat heartbeat_;
  std::optional<orchestrator::ScanProgress> last_;
  std::string previous_state_;
};

// Prints where the results are, or why the scan stopped and how to resume it. Returns the exit
// code: 0 done, 3 stopped by a fault, 4 paused.
int ReportScanOutcome(const orchestrator::ScanOutcome& outcome);

}  // namespace avc::cli
