// avc scan: one scan of a plant in the cell, from the devices to the traits, as the scan state
// machine (orchestrator/scan_states.h) walks it: CHECK_DEVICES, LOAD_CALIBRATION, FRAME,
// INITIAL_CAPTURE, ACTIVE_VISION, PRUNE_VIEWS, BUILD, MERGE_CLUSTER, SURFACE, TRAITS, REPORT.
// Everything lands in the scan directory, and scan.json there says how far it got, so
// `avc scan --resume DIR` continues a scan that was stopped, faulted or killed.

#include <fmt/format.h>

#include <filesystem>
#include <iostream>
#include <memory>
#include <set>
#include <string>
#include <utility>

#include "core/bus/bus.h"
#include "core/stage/stage_client.h"
#include "drivers/client/cell_client.h"
#include "orchestrator/scan_options.h"
#include "orchestrator/scan_run.h"
#include "orchestrator/scan_states.h"
#include "tools/avc/auth_flags.h"
#include "tools/avc/bus_flags.h"
#include "tools/avc/commands.h"
#include "tools/avc/config_flags.h"
#include "tools/avc/envelope_flags.h"
#include "tools/avc/run_guarded.h"
#include "tools/avc/scan_flags.h"
#include "tools/avc/scan_progress.h"

namespace avc::cli {
namespace {

namespace fs = std::filesystem;
using orchestrator::ScanState;

struct ScanArgs {
  std::string dir;
  std::string calibration;
  bool resume = false;
  bool states = false;
  ConfigFlags config;
  EnvelopeFlags envelope;  // envelope.* shorthands that take five numbers (--keep-out)
  AuthFlags auth;
  bus::BusFlags bus;
};

int RunScanCommand(const ScanArgs& args) {
  if (args.states) {
    std::cout << orchestrator::FormatStateTable();
    return 0;
  }
  if (args.dir.empty()) throw std::invalid_argument("give the scan directory (or --states)");
  const fs::path dir = args.dir;
  const bool exists = fs::exists(dir / "scan.json");
  if (args.resume && !exists) {
    throw std::runtime_error(dir.string() + " holds no scan (no scan.json) to resume");
  }
  if (!args.resume && exists) {
    throw std::runtime_error(dir.string() +
                             " already holds a scan; `avc scan --resume DIR` continues it");
  }
  if (!exists && args.calibration.empty()) {
    throw std::invalid_argument(
        "--calibration FILE is required for a new scan (the cell's calibration.yaml, from "
        "`avc calibrate`)");
  }

  ConfigFlags config = args.config;
  for (config::Assignment& setting : EnvelopeSettings(args.envelope)) {
    config.shorthands.push_back(std::move(setting));
  }
  const auto& table = orchestrator::ScanOptionTable();
  const orchestrator::ScanOptions scan = LoadOptions(table, config);
  orchestrator::ScanRunOptions options = scan.RunOptions();
  options.scan_dir = dir;
  options.calibration_file = args.calibration;
  options.configuration = table.ToToml(scan);

  bus::Bus bus(bus::ResolveBusOptions(args.bus, "avc-scan"));
  bus::EventLoop loop;
  bus.AttachTo(loop);
  loop.QuitOnTerminationSignals();
  options.stop_requested = [&loop] { return loop.quitting(); };
  client::CellClient cell(bus, loop, "avc-scan", SenderKey(args.auth, bus.cell()));
  stage::StageClient stages(bus, loop, "avc-scan");

  ScanStateBroadcast broadcast(bus, loop);
  options.on_kept_cameras = [&broadcast](const std::string& id, const auto& cameras) {
    broadcast.PublishKeptCameras(id, cameras);
  };
  const orchestrator::ScanOutcome outcome =
      orchestrator::RunScan(cell, stages, options, [&](const auto& p) { broadcast(p); });
  std::cerr << "\n";
  return ReportScanOutcome(outcome);
}

}  // namespace

void RegisterScan(CLI::App& root, int* exit_code) {
  auto args = std::make_shared<ScanArgs>();
  CLI::App* command = root.add_subcommand(
      "scan",
      "Scan a plant in the cell, unattended: check the devices, load the calibration, frame the\n"
      "plant, take the 3x10 orbit, add next-best views until every part of the plant proxy is\n"
      "seen well (Algorithm 1), drop redundant views, then reconstruct (masks, proxy, MVS),\n"
      "merge and cluster, surface and measure traits. This process only sequences: it needs\n"
      "avc robot, avc turntable and avc camera (real or `avc sim cell`) and the services that\n"
      "compute, avc planner, avc builder, avc clusterer and avc surfacer, READY on the bus\n"
      "(on this machine or others: `avc up launch/lab-three-hosts.toml`).\n"
      "Writes DIR/images/, cameras.json, colmap/, calibration.yaml, model/ (ppr.bt, points.ply,\n"
      "merged.ply, clusters.ply, mesh.ply, traits.csv, traits.json), report.json, report.html\n"
      "and scan.json, which is saved after every step: `avc scan --resume DIR` continues after a\n"
      "stop, a fault or a crash without capturing again what is on disk.\n"
      "Exit codes: 0 done, 3 stopped by a fault (the message says what), 4 paused by a signal.\n"
      "\n"
      "Example: avc scan /data/plant-042 --calibration /data/cal-2026-11-23/calibration.yaml");
  command->add_option("dir", args->dir, "scan directory (created)");
  command->add_option("--calibration", args->calibration, "the cell's calibration.yaml")
      ->check(CLI::ExistingFile);
  command->add_flag("--resume", args->resume, "continue the scan in DIR where it stopped");
  command->add_flag("--states", args->states,
                    "print the scan's states, the services each needs and where each may go");
  AddScanOptionFlags(command, &args->config);
  AddShorthandSwitch(command, &args->config, "--jpeg", "capture.encoding", "jpeg",
                     "keep the camera's JPEG (default: lossless PNG)");
  AddEnvelopeFlags(command, &args->envelope);
  AddSenderKeyFlag(command, &args->auth);
  AddBusFlags(command, &args->bus);
  SetGuardedRun(command, exit_code, [args] { return RunScanCommand(*args); });
}

}  // namespace avc::cli
