// avc demo: the main job on the simulated cell, from one command. It brings up the simulated cell
// and its drivers with `avc up` (a launch file written into the output folder), calibrates that
// cell over a chessboard the way a lab would (or loads a calibration: --calibration, or the one
// an earlier demo left in the cache), then runs `avc scan` on a plant and prints where the
// results are.

#include <fmt/format.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "core/bus/bus.h"
#include "core/calibration/cell/calibration_yaml.h"
#include "core/calibration/pipeline/calibrate_cell.h"
#include "core/eval/eval_command.h"
#include "core/eval/leaf_figures.h"
#include "core/eval/report_text.h"
#include "core/launch/find_program.h"
#include "core/stage/stage_client.h"
#include "drivers/client/cell_client.h"
#include "orchestrator/scan_options.h"
#include "orchestrator/scan_run.h"
#include "services/calibrator/calibration_collector.h"
#include "sim/cell/cell_fixtures.h"
#include "sim/scene/plant.h"
#include "tools/avc/bus_flags.h"
#include "tools/avc/commands.h"
#include "tools/avc/config_flags.h"
#include "tools/avc/demo_cell.h"
#include "tools/avc/run_guarded.h"
#include "tools/avc/scan_flags.h"
#include "tools/avc/scan_progress.h"

namespace avc::cli {
namespace {

namespace fs = std::filesystem;
using std::chrono::milliseconds;

struct DemoArgs {
  std::string dir;
  std::string plant = "broadleaf";
  std::string mesh;
  std::string calibration;
  bool recalibrate = false;
  double time_scale = 10;
  ConfigFlags config;  // the scan's options (orchestrator/scan_options.h)
  bus::BusFlags bus;
};

// A calibration of the simulated cell from an earlier demo: the simulated cell is the same on
// every run (one cell seed), so it need not be calibrated again. Empty without a home folder.
fs::path CachedCalibration() {
  const char* cache = std::getenv("XDG_CACHE_HOME");
  const char* home = std::getenv("HOME");
  if (cache != nullptr && *cache != '\0') return fs::path(cache) / "avc/sim-cell-calibration.yaml";
  if (home != nullptr && *home != '\0')
    return fs::path(home) / ".cache/avc/sim-cell-calibration.yaml";
  return {};
}

fs::path ChooseDemoDir(const DemoArgs& args) {
  if (!args.dir.empty()) return args.dir;
  const std::string name =
      "avc-demo-" + (args.mesh.empty() ? args.plant : fs::path(args.mesh).stem().string());
  fs::path candidate = fs::current_path() / name;
  for (int suffix = 2; fs::exists(candidate); ++suffix) {
    candidate = fs::current_path() / (name + "-" + std::to_string(suffix));
  }
  return candidate;
}

DemoCellOptions CellOptions(const DemoArgs& args, const fs::path& work_dir) {
  DemoCellOptions options;
  options.avc_binary = launch::SelfExecutableDir() / "avc";
  options.work_dir = work_dir;
  options.bus = bus::ResolveBusOptions(args.bus, "avc-demo");
  options.sim_args = {"--time-scale", fmt::format("{}", args.time_scale)};
  options.robot_args = sim::RobotEnvelopeArguments(sim::NominalCellEnvelope());
  return options;
}

// Calibrates the simulated cell over a chessboard (what `avc calibrate` does in
// sim-calibration.toml) and returns the calibration file.
fs::path CalibrateSimulatedCell(const DemoArgs& args, const fs::path& work_dir) {
  std::cerr << "calibrating the simulated cell over a chessboard (once; kept for later demos)\n";
  DemoCellOptions options = CellOptions(args, work_dir);
  for (const char* arg : {"--chessboard", "9x6", "--samples", "4", "--background", "plain"}) {
    options.sim_args.push_back(arg);
  }
  DemoCell cell(options);
  bus::Bus bus(options.bus);
  bus::EventLoop loop;
  bus.AttachTo(loop);
  client::CellClient client(bus, loop, "avc-demo", cell.key());
  calibrator::CollectOptions collect;
  collect.folder = work_dir / "dataset";
  collect.board.cols = 9;
  collect.board.rows = 6;
  collect.board.square_size = 0.025;
  collect.plan.envelope = kinematics::PlanningEnvelope(sim::NominalCellEnvelope());
  try {
    const calibration::CalibrationDataset dataset =
        calibrator::CollectCalibrationDataset(client, collect, [](const std::string& what) {
          std::cerr << "  " << what << (isatty(STDERR_FILENO) ? "\x1b[K\r" : "\n") << std::flush;
        });
    std::cerr << "\n";
    const calibration::CellCalibration result =
        calibration::CalibrateCell(dataset, calibration::CalibrateOptions{});
    const fs::path file = work_dir / "calibration.yaml";
    calibration::SaveCalibration(result, file);
    std::cerr << fmt::format("  calibration: reprojection RMS {:.3f} px, turntable {:.3f} mm\n",
                             result.residuals.hand_eye_rms_px,
                             result.residuals.turntable_centre_rms_mm);
    return file;
  } catch (const std::exception& error) {
    throw std::runtime_error(
        fmt::format("calibrating the simulated cell: {}\n{}", error.what(), cell.LogTail()));
  }
}

fs::path ChooseCalibration(const DemoArgs& args, const fs::path& dir) {
  if (!args.calibration.empty()) return args.calibration;
  const fs::path cached = CachedCalibration();
  if (!args.recalibrate && !cached.empty() && fs::exists(cached)) {
    std::cerr << "calibration: " << cached.string() << " (from an earlier demo; --recalibrate "
              << "makes a new one)\n";
    return cached;
  }
  const fs::path made = CalibrateSimulatedCell(args, dir / "calibration-run");
  if (!cached.empty()) {
    std::error_code ignored;  // a cache that cannot be written only costs the next demo time
    fs::create_directories(cached.parent_path(), ignored);
    fs::copy_file(made, cached, fs::copy_options::overwrite_existing, ignored);
  }
  return made;
}

int RunDemo(const DemoArgs& args) {
  // The scan's options first: a bad one is refused before anything starts.
  const auto& table = orchestrator::ScanOptionTable();
  orchestrator::ScanOptions scan_defaults;
  scan_defaults.envelope = sim::NominalCellEnvelope();
  const orchestrator::ScanOptions scan_options = LoadOptions(table, args.config, scan_defaults);
  const fs::path dir = ChooseDemoDir(args);
  fs::create_directories(dir);
  std::cerr << "avc demo: results go to " << dir.string() << "\n";
  const fs::path calibration = ChooseCalibration(args, dir);

  // The truth the simulated plant was made from, in the calibrated frame, for the scores.
  sim::RenderDatasetOptions scene;
  if (args.mesh.empty()) {
    scene.preset = sim::ParsePreset(args.plant);
  } else {
    scene.mesh_file = args.mesh;
  }
  WriteGroundTruthMesh(scene, calibration::LoadCalibration(calibration), dir / "gt_mesh.ply");

  DemoCellOptions options = CellOptions(args, dir / "cell");
  if (args.mesh.empty()) {
    options.sim_args.insert(options.sim_args.end(), {"--plant", args.plant});
  } else {
    options.sim_args.insert(options.sim_args.end(), {"--mesh", fs::absolute(args.mesh).string()});
  }
  options.record_to = fs::absolute(dir / "scan.lcmlog");
  DemoCell cell(options);
  bus::Bus bus(options.bus);
  bus::EventLoop loop;
  bus.AttachTo(loop);
  loop.QuitOnTerminationSignals();
  client::CellClient client(bus, loop, "avc-scan", cell.key());
  stage::StageClient stages(bus, loop, "avc-scan");

  orchestrator::ScanRunOptions scan = scan_options.RunOptions();
  scan.scan_dir = dir;
  scan.calibration_file = calibration;
  scan.configuration = table.ToToml(scan_options);
  scan.stop_requested = [&loop] { return loop.quitting(); };
  ScanStateBroadcast broadcast(bus, loop);
  scan.on_kept_cameras = [&broadcast](const std::string& id, const auto& cameras) {
    broadcast.PublishKeptCameras(id, cameras);
  };
  const orchestrator::ScanOutcome outcome =
      orchestrator::RunScan(client, stages, scan, [&](const auto& p) { broadcast(p); });
  std::cerr << "\n";
  const int code = ReportScanOutcome(outcome);
  if (outcome.state != orchestrator::ScanState::kDone) {
    std::cerr << cell.LogTail() << "\n";
    return code;
  }
  // The mesh against the truth (the plant's every organ, with a line per organ), then the
  // leaves alone last, where the eye lands: the whole-scene figures count the pot and soil,
  // which the masks leave out on purpose.
  eval::EvalCommandOptions evaluation;
  evaluation.ground_truth = dir / "gt_mesh.ply";
  evaluation.reconstruction = dir / "model/mesh.ply";
  evaluation.cameras = dir / "cameras.json";
  evaluation.json_output = dir / "model/mesh_eval.json";
  const nlohmann::json report = eval::RunEvalCommand(evaluation);
  std::cout << "the mesh against the simulated plant (pot and soil left out by design):\n"
            << eval::FormatSummary(report) << eval::FormatLeafFigures(eval::LeafFigures(report));
  return code;
}

}  // namespace

void RegisterDemo(CLI::App& root, int* exit_code) {
  auto args = std::make_shared<DemoArgs>();
  CLI::App* command = root.add_subcommand(
      "demo",
      "The whole job on the simulated cell, no hardware needed: starts the simulated cell and\n"
      "its drivers (avc up), calibrates the cell over a chessboard the first time (later demos\n"
      "reuse it from ~/.cache/avc), scans the plant with active vision and reconstructs it:\n"
      "images, cameras, calibration, plant proxy, points, clusters, mesh, traits, the LCM log\n"
      "(scan.lcmlog), report.json and report.html, all in DIR (default ./avc-demo-PLANT). Same\n"
      "as `avc scan` on a simulated cell; `avc scan --resume DIR` continues an interrupted demo\n"
      "while the cell runs (launch DIR/cell/launch.toml with avc up).\n"
      "\n"
      "Example: avc demo --plant strap");
  command->add_option("dir", args->dir, "output folder (default ./avc-demo-PLANT)");
  command->add_option("--plant", args->plant, "preset plant: rosette, broadleaf, strap or bushy")
      ->capture_default_str()
      ->check(CLI::IsMember({"rosette", "broadleaf", "strap", "bushy"}));
  command->add_option("--mesh", args->mesh, "scan this mesh (PLY, OBJ, OFF) instead of a preset")
      ->check(CLI::ExistingFile);
  command->add_option("--calibration", args->calibration, "use this calibration.yaml")
      ->check(CLI::ExistingFile);
  command->add_flag("--recalibrate", args->recalibrate,
                    "calibrate again instead of the cached one");
  command
      ->add_option("--time-scale", args->time_scale,
                   "simulated seconds per real second (robot and turntable motion)")
      ->capture_default_str()
      ->check(CLI::Range(0.1, 100.0));
  AddScanOptionFlags(command, &args->config);
  AddBusFlags(command, &args->bus);
  SetGuardedRun(command, exit_code, [args] { return RunDemo(*args); });
}

}  // namespace avc::cli
