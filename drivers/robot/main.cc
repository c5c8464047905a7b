// avc-robot: the UR5 driver process. Connects to the controller (RTDE 30004, secondary 30002,
// dashboard 29999), publishes ROBOT_STATE and executes ROBOT_COMMAND within a safety envelope.

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <vector>

#include "core/bus/service_runtime.h"
#include "drivers/robot/robot_node.h"

int main(int argc, char** argv) {
  CLI::App app{"avc-robot: UR5 driver (RTDE, URScript, dashboard) on the AVC bus"};
  avc::bus::BusFlags bus_flags;
  avc::robot::RobotNodeConfig config;
  std::optional<double> table_z;
  std::vector<double> keep_out;
  app.add_option("--lcm-url", bus_flags.lcm_url, "control LCM URL");
  app.add_option("--bulk-url", bus_flags.bulk_url, "bulk LCM URL");
  app.add_option("--cell", bus_flags.cell, "cell id (channel prefix)");
  app.add_option("--host", config.host, "controller address")->capture_default_str();
  app.add_option("--rtde-port", config.rtde_port, "RTDE port")->capture_default_str();
  app.add_option("--secondary-port", config.secondary_port, "secondary (script) port")
      ->capture_default_str();
  app.add_option("--dashboard-port", config.dashboard_port, "dashboard port")
      ->capture_default_str();
  app.add_option("--table-z", table_z, "table plane height in the base frame, m");
  app.add_option("--keep-out", keep_out, "keep-out cylinder: x y radius z_min z_max (base, m)")
      ->expected(5);
  app.add_option("--max-joint-speed", config.envelope.max_joint_speed_rad_s, "rad/s")
      ->capture_default_str();
  app.add_option("--max-linear-speed", config.envelope.max_linear_speed_m_s, "m/s")
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  config.envelope.table_z_base_m = table_z;
  if (keep_out.size() == 5) {
    config.envelope.keep_out = avc::robot::KeepOutCylinder{
        Eigen::Vector2d(keep_out[0], keep_out[1]), keep_out[2], keep_out[3], keep_out[4]};
  }
  try {
    avc::bus::ServiceRuntime runtime(config.service, bus_flags);
    avc::robot::RobotNode node(runtime.bus(), config);
    runtime.heartbeat().Set(avc::bus::ServiceState::kReady, "connected to " + config.host);
    int exit_code = 0;
    // Poll at the CB3 control rate; a lost controller ends the process (the launcher restarts
    // it) rather than driving blind.
    runtime.loop().AddTimer(
        std::chrono::milliseconds(8),
        [&] {
          try {
            node.Poll();
          } catch (const std::exception& error) {
            std::fprintf(stderr, "avc-robot: %s\n", error.what());
            runtime.heartbeat().Set(avc::bus::ServiceState::kError, error.what());
            exit_code = 1;
            runtime.loop().Quit(1);
          }
        },
        true);
    const int run_code = runtime.Run();
    return exit_code != 0 ? exit_code : run_code;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "avc-robot: %s\n", error.what());
    return 1;
  }
}
