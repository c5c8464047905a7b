#include "tools/avc/scan_progress.h"

#include <fmt/format.h>
#include <unistd.h>

#include <iostream>
#include <string>

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

int ReportScanOutcome(const orchestrator::ScanOutcome& outcome) {
  const std::string dir = outcome.scan_dir.string();
  switch (outcome.state) {
    case ScanState::kDone:
      std::cout << fmt::format(
          "scan done: {} images taken now, {} already on disk\n"
          "  {}/model/mesh.ply, traits.csv; report: {}/report.json\n",
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
