// avc sim cell: the live simulated cell. One process serves the UR5 (RTDE, primary, secondary,
// dashboard), the LT360 (pty) and the camera (PTP/IP) on one clock, so avc-robot, avc turntable
// and avc camera run their real back-ends against it exactly as against hardware.

#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "core/bus/service_runtime.h"
#include "core/util/log.h"
#include "sim/emulators/cell/simulated_cell.h"
#include "tools/avc/bus_flags.h"
#include "tools/avc/commands.h"
#include "tools/avc/run_guarded.h"
#include "tools/avc/sim_scene_flags.h"

namespace avc::cli {
namespace {

struct SimCellArgs {
  SimSceneArgs scene;
  sim::SimulatedCellOptions cell;
  int camera_port = 15740;
  bus::BusFlags bus;
};

int RunSimCell(SimCellArgs args) {
  ResolveSimScene(args.scene);
  sim::SimulatedCellOptions& options = args.cell;
  options.scene = sim::MakeScene(args.scene.options);
  options.cell = sim::MakeCell(args.scene.options);
  options.render = args.scene.options.render;
  options.noise = args.scene.options.noise;
  options.camera.port = args.camera_port;

  bus::ServiceRuntime runtime("avc-sim", args.bus);
  sim::SimulatedCell cell(options);
  std::cout << cell.Describe() << std::endl;
  log::Info("simulated cell up: {} triangles; {}", options.scene.mesh.faces.size(),
            cell.Describe());
  runtime.heartbeat().Set(bus::ServiceState::kReady,
                          fmt::format("arm :{} table {} camera {}", cell.arm().rtde_port(),
                                      cell.turntable_device(), cell.camera_port()));
  // Frames rendered so far, for `avc status`.
  runtime.loop().AddTimer(
      std::chrono::seconds(1),
      [&] {
        runtime.heartbeat().Set(
            bus::ServiceState::kReady,
            fmt::format("arm :{} table {} camera {}; {} frames rendered", cell.arm().rtde_port(),
                        cell.turntable_device(), cell.camera_port(), cell.frames_rendered()));
      },
      /*repeating=*/true);
  return runtime.Run();
}

}  // namespace

void RegisterSimCell(CLI::App& sim, int* exit_code) {
  auto args = std::make_shared<SimCellArgs>();
  sim::SimulatedCellOptions& c = args->cell;
  c.table.speed_deg_s = 90;
  c.table.accel_deg_s2 = 180;
  c.table.sigma_deg = 0.05;
  c.link_dir = "/tmp/avc-sim";
  CLI::App* command = sim.add_subcommand(
      "cell",
      "Run the simulated cell: UR5, LT360 and camera emulators on one clock.\n"
      "The drivers connect to it as to real hardware: avc-robot to the UR5 ports, avc turntable\n"
      "to <link-dir>/lt360, avc camera to ptpip:127.0.0.1:<camera-port> (model \"PTP/IP "
      "Camera\").\n"
      "Each capture renders the plant from the true camera pose; <link-dir>/truth.jsonl logs it\n"
      "(appended to, so it spans restarts).\n"
      "Example: avc sim cell --plant strap --time-scale 4 --link-dir /tmp/avc-sim");
  AddSimSceneFlags(*command, args->scene);
  command->add_option("--time-scale", c.time_scale, "simulated seconds per real second")
      ->capture_default_str()
      ->check(CLI::Range(0.01, 1000.0));
  command->add_option("--rtde-port", c.arm.rtde_port, "UR5 RTDE port (0 = any free port)")
      ->capture_default_str();
  command->add_option("--primary-port", c.arm.primary_port, "UR5 primary port")
      ->capture_default_str();
  command->add_option("--secondary-port", c.arm.secondary_port, "UR5 secondary port")
      ->capture_default_str();
  command->add_option("--dashboard-port", c.arm.dashboard_port, "UR5 dashboard port")
      ->capture_default_str();
  command->add_flag("--powered", c.arm.powered, "start the arm powered with brakes released");
  command->add_option("--camera-port", args->camera_port, "PTP/IP port (0 = any free port)")
      ->capture_default_str();
  command
      ->add_option("--capture-latency", c.camera.capture_latency_s,
                   "simulated seconds from shutter to image on the card")
      ->capture_default_str();
  command->add_flag("--png", c.png, "store frames as PNG instead of JPEG");
  command->add_option("--table-speed", c.table.speed_deg_s, "turntable speed, deg/s")
      ->capture_default_str();
  command->add_option("--table-sigma", c.table.sigma_deg, "turntable angle noise per move, deg")
      ->capture_default_str();
  command
      ->add_option("--link-dir", c.link_dir, "where to put the lt360 pty symlink and truth.jsonl")
      ->capture_default_str();
  AddBusFlags(command, &args->bus);
  SetGuardedRun(command, exit_code, [args] { return RunSimCell(*args); });
}

}  // namespace avc::cli
