// avc calibrate: calibrate the cell (paper §2.1). `collect` drives the arm, table and camera over
// a chessboard lying on the turntable and writes a dataset (images + robot poses + table
// angles); `solve` turns a dataset into calibration.yaml; with no subcommand, both.

#include <fmt/format.h>
#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>

#include "core/bus/bus.h"
#include "core/calibration/cell/calibration_yaml.h"
#include "core/calibration/pipeline/calibrate_cell.h"
#include "core/calibration/pipeline/calibration_dataset.h"
#include "core/calibration/pipeline/intrinsics_file.h"
#include "drivers/client/cell_client.h"
#include "services/calibrator/calibration_collector.h"
#include "tools/avc/auth_flags.h"
#include "tools/avc/bus_flags.h"
#include "tools/avc/commands.h"
#include "tools/avc/envelope_flags.h"
#include "tools/avc/run_guarded.h"

namespace avc::cli {
namespace {

namespace fs = std::filesystem;
using std::chrono::milliseconds;

struct CalibrateArgs {
  std::string folder;
  std::string board = "9x6";
  double square_m = 0.025;
  calibrator::CalibrationPlanOptions plan;
  EnvelopeFlags envelope;  // the poses' moves are planned inside it
  // Where the turntable's top centre roughly is in the robot base frame (metres), for planning.
  std::vector<double> table_in_base;
  std::string output;              // calibration.yaml; default <folder>/calibration.yaml
  std::string intrinsics;          // known intrinsics to use instead of estimating them
  bool choose_distortion = false;  // the distortion model by held-out views
  AuthFlags auth;
  bus::BusFlags bus;
};

calibration::Chessboard ParseBoard(const std::string& text, double square_m) {
  calibration::Chessboard board;
  char x = 0;
  std::istringstream in(text);
  if (!(in >> board.cols >> x >> board.rows) || x != 'x' || !in.eof()) {
    throw std::invalid_argument("--board wants COLSxROWS inner corners, e.g. 9x6; got '" + text +
                                "'");
  }
  board.square_size = square_m;
  if (const std::string problem = board.Validate(); !problem.empty()) {
    throw std::invalid_argument("--board: " + problem);
  }
  return board;
}

// One line per step on a terminal (rewritten in place), one line each in a log.
void Progress(const std::string& what) {
  std::cerr << what << (isatty(STDERR_FILENO) ? "\x1b[K\r" : "\n") << std::flush;
}

int RunCollect(const CalibrateArgs& args) {
  calibrator::CollectOptions options;
  options.folder = args.folder;
  options.board = ParseBoard(args.board, args.square_m);
  options.plan = args.plan;
  options.plan.envelope = PlanningEnvelopeOf(args.envelope);
  if (args.table_in_base.size() == 3) {
    // The table frame is not rotated against the base for planning; only its place matters.
    options.planning_cell.T_base_table = Eigen::Isometry3d::Identity();
    options.planning_cell.T_base_table.translation() << args.table_in_base[0],
        args.table_in_base[1], args.table_in_base[2];
  }
  bus::Bus bus(bus::ResolveBusOptions(args.bus, "avc-calibrate"));
  bus::EventLoop loop;
  bus.AttachTo(loop);
  client::CellClient cell(bus, loop, "avc-calibrate", SenderKey(args.auth, bus.cell()));
  const calibration::CalibrationDataset dataset =
      calibrator::CollectCalibrationDataset(cell, options, Progress);
  std::cerr << "\n";
  std::cout << fmt::format("wrote {} images and dataset.json to {}\n", dataset.shots.size(),
                           args.folder);
  return 0;
}

int RunSolve(const CalibrateArgs& args) {
  const calibration::CalibrationDataset dataset = calibration::LoadCalibrationDataset(args.folder);
  calibration::CalibrationDetails details;
  calibration::CalibrateOptions options;
  if (!args.intrinsics.empty()) {
    options.intrinsics.known = calibration::ReadIntrinsicsFile(args.intrinsics);
  }
  options.intrinsics.choose_distortion_model = args.choose_distortion;
  const calibration::CellCalibration result =
      calibration::CalibrateCell(dataset, options, &details, Progress);
  const fs::path output =
      args.output.empty() ? fs::path(args.folder) / "calibration.yaml" : fs::path(args.output);
  calibration::SaveCalibration(result, output);
  const calibration::CalibrationResiduals& r = result.residuals;
  std::cerr << "\n";
  std::cout << fmt::format(
      "calibration written to {}\n"
      "  intrinsics: fx {:.2f} fy {:.2f} cx {:.2f} cy {:.2f}, RMS {:.3f} px\n"
      "  hand-eye: {} poses, reprojection RMS {:.3f} px (closed form {:.3f}), pose residual "
      "{:.4f} deg / {:.3f} mm (median)\n",
      output.string(), result.intrinsics.fx, result.intrinsics.fy, result.intrinsics.cx,
      result.intrinsics.cy, r.intrinsics_rms_px, details.hand_eye_views, r.hand_eye_rms_px,
      details.closed_form_rms_px, r.hand_eye_rotation_deg, r.hand_eye_translation_mm);
  const calibration::TurntableAxis& axis = details.turntable_axis_base;
  std::cout << (result.turntable_calibrated
                    ? fmt::format("  turntable: {} angles, axis ({:.5f} {:.5f} {:.5f}) through "
                                  "({:.4f} {:.4f} {:.4f}) m in the base frame, RMS {:.3f} mm\n",
                                  details.turntable_views, axis.axis.x(), axis.axis.y(),
                                  axis.axis.z(), axis.centre.x(), axis.centre.y(), axis.centre.z(),
                                  r.turntable_centre_rms_mm)
                    : std::string("  turntable: not calibrated (no turntable shots); "
                                  "T_base_table is the board in the base frame, and a scan "
                                  "refuses this calibration\n"));
  std::cout << fmt::format(
      "  hand-eye kept: {}, leave-one-out {:.4f} deg / {:.3f} mm (the {}: {:.4f} deg / {:.3f} "
      "mm, {:.3f} px)\n",
      r.hand_eye_method, r.hand_eye_loo_rotation_deg, r.hand_eye_loo_translation_mm,
      r.alternative_method, r.alternative_loo_rotation_deg, r.alternative_loo_translation_mm,
      r.alternative_rms_px);
  std::cout << fmt::format(
      "  distortion model: {}{}\n", details.distortion_model,
      details.distortion_model_reason.empty() ? "" : " (" + details.distortion_model_reason + ")");
  for (const std::string& why : r.rejected) std::cout << "  left out: " << why << "\n";
  for (const std::string& warning : details.warnings) std::cout << "  warning: " << warning << "\n";
  return 0;
}

void AddCollectFlags(CLI::App& command, CalibrateArgs& args) {
  command.add_option("--board", args.board, "chessboard inner corners COLSxROWS")
      ->capture_default_str();
  command.add_option("--square", args.square_m, "chessboard square size, metres")
      ->capture_default_str();
  command
      .add_option("--table-in-base", args.table_in_base,
                  "turntable top centre in the robot base frame, x y z metres, measured roughly "
                  "(default: the simulated cell's 0.55 0 -0.2)")
      ->expected(3);
  command.add_option("--poses", args.plan.hand_eye_poses, "hand-eye poses")
      ->capture_default_str()
      ->check(CLI::Range(3, 100));
  command.add_option("--angles", args.plan.table_angles, "table angles over a full turn")
      ->capture_default_str()
      ->check(CLI::Range(3, 360));
  AddEnvelopeFlags(&command, &args.envelope);
  AddSenderKeyFlag(&command, &args.auth);
  AddBusFlags(&command, &args.bus);
}

}  // namespace

void RegisterCalibrate(CLI::App& root, int* exit_code) {
  auto args = std::make_shared<CalibrateArgs>();
  CLI::App* command = root.add_subcommand(
      "calibrate",
      "Calibrate the cell: intrinsics, hand-eye, robot-world and turntable axis.\n"
      "Lay the chessboard flat on the turntable, centred, then run this with avc robot, avc\n"
      "turntable and avc camera up (real or `avc sim cell --chessboard 9x6`). It collects images\n"
      "over the board and while the table turns into FOLDER, then solves FOLDER/calibration.yaml.\n"
      "`avc calibrate collect` and `avc calibrate solve` run the two halves on their own.");
  // Not required(): CLI11 gives a required positional the next word even when it names a
  // subcommand, so `avc calibrate solve FOLDER` read "solve" as the folder.
  command->add_option("folder", args->folder, "dataset folder (created)");
  AddCollectFlags(*command, *args);
  SetGuardedRun(command, exit_code, [args] {
    if (args->folder.empty()) {
      throw std::invalid_argument(
          "give the dataset FOLDER (or `avc calibrate collect FOLDER` / `avc calibrate solve "
          "FOLDER`)");
    }
    RunCollect(*args);
    return RunSolve(*args);
  });

  auto collect_args = std::make_shared<CalibrateArgs>();
  CLI::App* collect = command->add_subcommand(
      "collect", "Drive the cell over the board and write a dataset (images, poses, angles).");
  collect->add_option("folder", collect_args->folder, "dataset folder (created)")->required();
  AddCollectFlags(*collect, *collect_args);
  SetGuardedRun(collect, exit_code, [collect_args] { return RunCollect(*collect_args); });

  auto solve_args = std::make_shared<CalibrateArgs>();
  CLI::App* solve = command->add_subcommand(
      "solve", "Solve a dataset folder (dataset.json + images/) into calibration.yaml, offline.");
  solve->add_option("folder", solve_args->folder, "dataset folder")
      ->required()
      ->check(CLI::ExistingDirectory);
  solve->add_option("-o,--output", solve_args->output,
                    "calibration file (default: FOLDER/calibration.yaml)");
  solve
      ->add_option("--intrinsics", solve_args->intrinsics,
                   "use these camera intrinsics instead of estimating them: a calibration.yaml, "
                   "or an OpenCV file (YAML/XML) with camera_matrix and "
                   "distortion_coefficients (k1 k2 p1 p2 k3)")
      ->check(CLI::ExistingFile);
  solve->add_flag("--choose-distortion", solve_args->choose_distortion,
                  "choose the distortion terms (k1; k1 k2; k1 k2 p1 p2; k1 k2 p1 p2 k3) by the "
                  "reprojection of views held out of each fit, for few views of one board "
                  "(default: all five)");
  SetGuardedRun(solve, exit_code, [solve_args] { return RunSolve(*solve_args); });
}

}  // namespace avc::cli
