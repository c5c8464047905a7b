#include "tools/avc/scan_progress.h"

#include <fmt/format.h>
#include <unistd.h>

#include <avc/orchestrator_state_t.hpp>
#include <avc/scan_cameras_t.hpp>
#include <chrono>
#include <iostream>
#include <string>

#include "core/bus/channels.h"
#include "core/messages/camera_message.h"
#include "core/util/clock.h"

namespace avc::cli {
namespace {

using orchestrator::ScanState;

std::string Clock(double seconds) {
  const int s = static_cast<int>(seconds + 0.5);
  return s >= 60 ? fmt::format("{}m{:02d}s", s / 60, s % 60) : fmt::format("{}s", s);
}

}  // namespace

void ShowScanProgress(const orchestrator::ScanProgress& p) {
  std::string eta = "-";
  if (p.fraction > 0.05 && p.fraction < 1) eta = Clock(p.elapsed_s * (1 - p.fraction) / p.fraction);
  const int filled = static_cast<int>(p.fraction * 20 + 0.5);
  const std::string line =
      fmt::format("[{:<20}] {:3.0f}% {:<16} {:>3} images  {:>6} elapsed  eta {:>6}  {}",
                  std::string(filled, '#'), 100 * p.fraction, orchestrator::StateName(p.state),
                  p.captures, Clock(p.elapsed_s), eta, p.detail);
  const bool terminal = isatty(STDERR_FILENO);
  std::cerr << (terminal ? "\r" + line.substr(0, 160) + "\x1b[K" : line + "\n") << std::flush;
}

ScanStateBroadcast::ScanStateBroadcast(bus::Bus& bus, bus::EventLoop& loop)
    : bus_(bus),
      loop_(loop),
      timer_(loop.AddTimer(
          std::chrono::seconds(1), [this] { Publish(); }, /*repeating=*/true)),
      // Well inside the robot watchdog's 500 ms, so a busy moment of the loop is no silence.
      heartbeat_(bus, "avc-orchestrator", std::chrono::milliseconds(100)) {
  heartbeat_.Set(bus::ServiceState::kReady, "starting a scan");
}

ScanStateBroadcast::~ScanStateBroadcast() { loop_.CancelTimer(timer_); }

void ScanStateBroadcast::operator()(const orchestrator::ScanProgress& progress) {
  ShowScanProgress(progress);
  if (last_ && last_->state != progress.state) {
    previous_state_ = orchestrator::StateName(last_->state);
  }
  last_ = progress;
  Publish();
  const std::string state(orchestrator::StateName(progress.state));
  if (progress.state == ScanState::kFault) {
    heartbeat_.Set(bus::ServiceState::kError, progress.detail);
  } else if (progress.state == ScanState::kPaused || progress.state == ScanState::kDone) {
    heartbeat_.Set(bus::ServiceState::kReady, state);
  } else {
    heartbeat_.Set(bus::ServiceState::kBusy, state);
  }
}

void ScanStateBroadcast::PublishKeptCameras(const std::string& scan_id,
                                            const std::vector<camera::NamedCamera>& cameras) {
  avc::scan_cameras_t message{};
  message.scan_id = scan_id;
  for (const camera::NamedCamera& c : cameras) {
    message.cameras.push_back(messages::CameraToMessage(c.camera, c.name, "scan"));
  }
  message.num_cameras = static_cast<int32_t>(message.cameras.size());
  bus_.Publish(channels::kScanCameras, message);
}

void ScanStateBroadcast::Publish() {
  if (!last_) return;
  const orchestrator::ScanProgress& p = *last_;
  avc::orchestrator_state_t message{};
  message.scan_id = p.scan_id;
  message.scan_dir = p.scan_dir.string();
  message.state = orchestrator::StateName(p.state);
  message.previous_state = previous_state_;
  message.detail =
      p.interrupted ? fmt::format("{} (in {})", p.detail, orchestrator::StateName(*p.interrupted))
                    : p.detail;
  message.started_utime =
      SystemClock().NowMicros() - static_cast<int64_t>(1e6 * p.elapsed_s);  // of this run
  message.views_captured = p.captures;
  message.views_planned = 0;  // the planner decides as it goes
  message.fraction = p.fraction;
  message.eta_us = p.fraction > 0.05 && p.fraction < 1
                       ? static_cast<int64_t>(1e6 * p.elapsed_s * (1 - p.fraction) / p.fraction)
                       : -1;
  bus_.Publish(channels::kOrchestratorState, message);
}

int ReportScanOutcome(const orchestrator::ScanOutcome& outcome) {
  const std::string dir = outcome.scan_dir.string();
  switch (outcome.state) {
    case ScanState::kDone:
      std::cout << fmt::format(
          "scan done: {} images taken now, {} already on disk\n"
          "  mesh and traits: {}/model/mesh.ply, traits.csv\n"
          "  report: open {}/report.html in a browser (figures in report.json)\n",
          outcome.captured_now, outcome.reused, dir, dir);
      return 0;
    case ScanState::kPaused:
      std::cout << fmt::format(
          "scan paused; nothing captured is lost. Continue with:\n  avc scan --resume {}\n", dir);
      return 4;
    default:
      std::cout << fmt::format(
          "scan stopped: {}\nnothing captured is lost; fix the cause, then:\n"
          "  avc scan --resume {}\n",
          outcome.fault, dir);
      return 3;
  }
}

}  // namespace avc::cli
