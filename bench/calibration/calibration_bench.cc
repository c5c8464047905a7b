#include "bench/calibration/calibration_bench.h"

#include <fmt/format.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>

#include "bench/calibration/cell_calibration_run.h"
#include "bench/calibration/hand_eye/hand_eye_comparison.h"
#include "bench/calibration/hand_eye/hand_eye_trials.h"
#include "bench/calibration/turntable/turntable_trials.h"
#include "bench/registry.h"

namespace avc::bench {
namespace {

struct CalibrationBenchArgs {
  int trials = 200;
  bool skip_cell = false;
  CellCalibrationRunOptions cell;
  std::string real_data = (SharedDataDir() / "handeye_visp" / "data-eye-to-hand").string();
  std::string work_dir;
  bool json = false;
};

std::string FormatCellRun(const nlohmann::json& run) {
  const nlohmann::json& c = run["calibration"];
  const nlohmann::json& s = run["scan"];
  return fmt::format(
      "End to end in the simulated cell ({} hand-eye poses, {} table angles; table angle error "
      "{} deg per move):\n"
      "  reprojection RMS: intrinsics {:.3f} px, hand-eye chain {:.3f} px (closed form {:.3f})\n"
      "  scan path of {} views, calibrated vs true camera: centre {:.3f} mm median, {:.3f} p90, "
      "{:.3f} max; rotation {:.4f} deg median, {:.4f} p90, {:.4f} max\n",
      c["hand_eye_views"].get<int>(), c["turntable_views"].get<int>(),
      s["table_sigma_deg"].get<double>(), c["intrinsics_rms_px"].get<double>(),
      c["hand_eye_rms_px"].get<double>(), c["closed_form_rms_px"].get<double>(),
      s["views"].get<int>(), s["centre_error_mm"]["median"].get<double>(),
      s["centre_error_mm"]["p90"].get<double>(), s["centre_error_mm"]["max"].get<double>(),
      s["rotation_error_deg"]["median"].get<double>(), s["rotation_error_deg"]["p90"].get<double>(),
      s["rotation_error_deg"]["max"].get<double>());
}

int Run(CalibrationBenchArgs args) {
  nlohmann::json json;
  json["benchmark"] = "calibration";

  std::cerr << "hand-eye: Monte-Carlo trials\n";
  json["hand_eye"] = RunHandEyeBenchmark(args.trials);
  std::cout << FormatHandEyeTable(json["hand_eye"]) << "\n";

  std::cerr << "turntable: Monte-Carlo trials\n";
  TurntableTrialOptions turntable;
  turntable.trials = args.trials;
  json["turntable"] = RunTurntableTrials(turntable);
  std::cout << FormatTurntableTrials(json["turntable"]) << "\n";

  int exit_code = 0;
  if (!args.real_data.empty()) {
    std::cerr << "hand-eye: the real eye-to-hand set\n";
    try {
      json["real_eye_to_hand"] = RunRealEyeToHand(args.real_data);
      std::cout << FormatRealEyeToHand(json["real_eye_to_hand"]) << "\n";
    } catch (const std::exception& error) {
      std::cout << "the real eye-to-hand set failed: " << error.what() << "\n";
      json["real_eye_to_hand"] = {{"error", error.what()}};
      exit_code = 1;
    }
  }
  if (!args.skip_cell) {
    std::cerr << "end to end in the simulated cell\n";
    args.cell.work_dir = args.work_dir.empty()
                             ? std::filesystem::temp_directory_path() /
                                   fmt::format("avc-bench-calibration-{}", getpid())
                             : std::filesystem::path(args.work_dir);
    try {
      json["cell"] = RunCellCalibration(args.cell);
      std::cout << FormatCellRun(json["cell"]);
      std::cout << FormatHandEyeComparison(json["cell"]["hand_eye_methods"],
                                           "Hand-eye methods on the simulated cell's detections");
    } catch (const std::exception& error) {
      std::cout << "end to end in the simulated cell failed: " << error.what() << "\n";
      json["cell"] = {{"error", error.what()}};
      exit_code = 1;
    }
  }
  if (args.json) std::cout << json.dump() << "\n";
  return exit_code;
}

}  // namespace

int RunCalibrationBenchmark(const std::vector<std::string>& arguments) {
  CalibrationBenchArgs args;
  CLI::App app{
      "avc bench calibration: hand-eye and turntable Monte-Carlo trials against their baselines,\n"
      "and the whole calibration end to end in the simulated cell.",
      "avc bench calibration"};
  app.add_option("--trials", args.trials, "Monte-Carlo trials per case")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  app.add_flag("--skip-cell", args.skip_cell, "no end-to-end run in the simulated cell");
  app.add_option("--real-data", args.real_data, "the ViSP eye-to-hand set (\"\": skip it)")
      ->capture_default_str();
  app.add_option("--time-scale", args.cell.time_scale, "simulated cell clock")
      ->capture_default_str();
  app.add_option("--table-sigma", args.cell.table_sigma_deg,
                 "emulated table angle error per move, deg")
      ->capture_default_str();
  app.add_option("--port", args.cell.port, "multicast port of the control bus (bulk: +1)")
      ->capture_default_str();
  app.add_option("--work-dir", args.work_dir, "keep the dataset, calibration and logs here");
  app.add_flag("--json", args.json, "print the results as one JSON line at the end");
  if (const auto exit_code = ParseBenchmarkArguments(app, arguments)) return *exit_code;
  return Run(args);
}

}  // namespace avc::bench
