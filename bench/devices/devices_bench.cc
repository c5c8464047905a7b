#include "bench/devices/devices_bench.h"

#include <fmt/format.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "bench/devices/cell_processes.h"
#include "bench/registry.h"
#include "bench/summary.h"
#include "core/bus/bus.h"
#include "drivers/client/cell_client.h"
#include "sim/cell/cell_truth.h"
#include "sim/cell/view_selection.h"

namespace avc::bench {
namespace {
namespace fs = std::filesystem;
using std::chrono::milliseconds;

struct DevicesBenchArgs {
  int views = 8;
  std::vector<double> time_scales = {1, 10};
  int triangles = 40000;
  int port = 7760;  // control multicast port; bulk is port + 1
  std::string work_dir;
  bool json = false;
};

// One view of the plan: where the arm goes and where the table turns.
struct PlannedView {
  kinematics::JointVector q;
  double table_rad = 0;
};

// Views on two elevation rings on the arm's side, the table turning 360/N degrees per view,
// planned with the nominal cell as the drivers see it.
std::vector<PlannedView> PlanViews(int count) {
  const sim::CellTruth nominal = sim::NominalCell();
  const Eigen::Vector3d target(0, 0, 0.12);
  const double robot_azimuth = sim::RobotAzimuth(nominal);
  std::vector<PlannedView> views;
  kinematics::JointVector current;
  current << 0, -std::numbers::pi / 2, std::numbers::pi / 2, -std::numbers::pi / 2,
      -std::numbers::pi / 2, 0;
  for (int i = 0; i < count; ++i) {
    const double elevation = (i % 2 == 0 ? 15.0 : 35.0) * std::numbers::pi / 180;
    const double azimuth = robot_azimuth + ((i / 2) % 3 - 1) * 25.0 * std::numbers::pi / 180;
    const auto view = sim::FirstReachableView(nominal, target, 0.6, elevation, azimuth, current);
    if (!view) throw std::runtime_error(fmt::format("bench view {} is out of the arm's reach", i));
    views.push_back({view->q, 2 * std::numbers::pi * i / count});
    current = view->q;
  }
  return views;
}

struct ModeResult {
  double time_scale = 1;
  std::vector<double> move_s, rotate_s, capture_s, transfer_s, view_s;
  std::string error;
};

ModeResult RunMode(const DevicesBenchArgs& args, double time_scale,
                   const std::vector<PlannedView>& plan, const fs::path& work) {
  ModeResult result;
  result.time_scale = time_scale;
  CellProcessOptions options = LocalCellOptions(args.port, "bench", time_scale, work);
  options.triangles = args.triangles;
  options.stages = false;  // the devices alone
  CellProcesses cell(options);

  bus::Bus bus(ClientBusOptions(options, "avc-bench"));
  bus::EventLoop loop;
  bus.AttachTo(loop);
  client::CellClient client(bus, loop, "avc-bench", cell.key());
  try {
    client.WaitReady({"avc-sim", "avc-robot", "avc-turntable", "avc-camera"}, milliseconds(30000));
    client.Robot(avc::robot_command_t::KIND_POWER_ON, milliseconds(20000));
    client.Robot(avc::robot_command_t::KIND_BRAKE_RELEASE, milliseconds(20000));
    for (size_t i = 0; i < plan.size(); ++i) {
      const int64_t start = MonotonicMicros();
      result.move_s.push_back(client.MoveJoints(plan[i].q, milliseconds(60000)));
      result.rotate_s.push_back(client.TurntableGoto(plan[i].table_rad, milliseconds(60000)));
      const client::CapturedView view = client.Capture(
          fmt::format("view_{:04d}", i), avc::image_t::ENCODING_JPEG, milliseconds(60000));
      result.capture_s.push_back(view.request_to_sent_s);
      result.transfer_s.push_back(view.request_to_done_s - view.request_to_sent_s);
      result.view_s.push_back((MonotonicMicros() - start) * 1e-6);
      std::cerr << fmt::format("  {}x clock: view {}/{} {:.2f} s\n", time_scale, i + 1, plan.size(),
                               result.view_s.back());
    }
  } catch (const std::exception& error) {
    result.error = fmt::format("{}\n{}", error.what(), cell.LogTails());
  }
  return result;
}

nlohmann::json StepJson(const std::vector<double>& values) {
  const Summary s = Summarize(values);
  return {{"count", s.count}, {"median_s", s.median}, {"max_s", s.max}};
}

int Run(const DevicesBenchArgs& args) {
  const std::vector<PlannedView> plan = PlanViews(args.views);
  const fs::path work = args.work_dir.empty() ? fs::temp_directory_path() /
                                                    fmt::format("avc-bench-devices-{}", getpid())
                                              : fs::path(args.work_dir);
  std::vector<ModeResult> modes;
  for (const double scale : args.time_scales) {
    std::cerr << fmt::format("simulated cell at {}x real time, {} views\n", scale, plan.size());
    modes.push_back(RunMode(args, scale, plan, work / fmt::format("clock-{}x", scale)));
  }
  nlohmann::json json;
  json["benchmark"] = "devices";
  json["views"] = args.views;
  json["triangles"] = args.triangles;
  std::cout << fmt::format(
      "Time per captured view in the simulated cell ({} views, 1280x960, {} triangles; medians, "
      "s)\n"
      "{:>8} {:>8} {:>8} {:>9} {:>9} {:>8}\n",
      args.views, args.triangles, "clock", "move", "rotate", "capture", "transfer", "view");
  int exit_code = 0;
  for (const ModeResult& mode : modes) {
    nlohmann::json entry;
    entry["time_scale"] = mode.time_scale;
    if (!mode.error.empty()) {
      std::cout << fmt::format("{:>7}x failed: {}\n", mode.time_scale, mode.error);
      entry["error"] = mode.error;
      exit_code = 1;
    } else {
      std::cout << fmt::format("{:>7}x {:8.3f} {:8.3f} {:9.3f} {:9.3f} {:8.3f}\n", mode.time_scale,
                               Summarize(mode.move_s).median, Summarize(mode.rotate_s).median,
                               Summarize(mode.capture_s).median, Summarize(mode.transfer_s).median,
                               Summarize(mode.view_s).median);
      entry["move"] = StepJson(mode.move_s);
      entry["rotate"] = StepJson(mode.rotate_s);
      entry["capture"] = StepJson(mode.capture_s);
      entry["transfer"] = StepJson(mode.transfer_s);
      entry["view"] = StepJson(mode.view_s);
    }
    json["modes"].push_back(entry);
  }
  if (modes.size() >= 2 && modes[0].error.empty() && modes[1].error.empty()) {
    const double ratio =
        Summarize(modes[0].view_s).median / std::max(1e-9, Summarize(modes[1].view_s).median);
    std::cout << fmt::format("{}x clock: {:.1f} times faster per view than {}x\n",
                             modes[1].time_scale, ratio, modes[0].time_scale);
    json["speedup"] = ratio;
  }
  std::cout << "capture = request to image sent (settings, exposure, render, download, encode);\n"
               "transfer = image sent to DONE (bulk bus, reassembly, acknowledgement)\n";
  if (args.json) std::cout << json.dump() << "\n";
  return exit_code;
}

}  // namespace

int RunDevicesBenchmark(const std::vector<std::string>& arguments) {
  DevicesBenchArgs args;
  CLI::App app{
      "avc bench devices: time per captured view in the simulated cell (move, rotate, capture,\n"
      "transfer), every driver a separate process on the real protocols, at several clocks.",
      "avc bench devices"};
  app.add_option("--views", args.views, "views per clock")
      ->capture_default_str()
      ->check(CLI::Range(1, 200));
  app.add_option("--time-scales", args.time_scales, "simulated seconds per real second, each run")
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--triangles", args.triangles, "plant triangles")->capture_default_str();
  app.add_option("--port", args.port, "multicast port of the control bus (bulk: +1)")
      ->capture_default_str();
  app.add_option("--work-dir", args.work_dir, "keep logs here (default: a temporary directory)");
  app.add_flag("--json", args.json, "print the results as one JSON line at the end");
  if (const auto exit_code = ParseBenchmarkArguments(app, arguments)) return *exit_code;
  return Run(args);
}

}  // namespace avc::bench
