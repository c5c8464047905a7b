// avc robot: the avc-robot service, the UR5 driver. Connects to the controller (RTDE 30004,
// secondary 30002, dashboard 29999), publishes ROBOT_STATE and executes ROBOT_COMMAND within a
// safety envelope. A lost controller is reconnected (heartbeat ERROR meanwhile), never a reason
// to exit; SIGTERM stops any motion and ends the process cleanly.

#include <memory>
#include <optional>
#include <vector>

#include "core/bus/service_runtime.h"
#include "drivers/robot/robot_node.h"
#include "tools/avc/auth_flags.h"
#include "tools/avc/bus_flags.h"
#include "tools/avc/commands.h"
#include "tools/avc/envelope_flags.h"
#include "tools/avc/run_guarded.h"

namespace avc::cli {
namespace {

struct RobotArgs {
  robot::RobotNodeConfig config;
  EnvelopeFlags envelope;
  int64_t watchdog_timeout_ms = 500;
  AuthFlags auth;
  bus::BusFlags bus;
};

int RunRobot(RobotArgs args) {
  robot::RobotNodeConfig& config = args.config;
  ApplyEnvelopeFlags(args.envelope, &config.envelope);
  config.watchdog_timeout = std::chrono::milliseconds(args.watchdog_timeout_ms);
  bus::ServiceRuntime runtime(config.service, args.bus);
  config.auth = DriverAuth(args.auth, runtime.bus().cell());
  robot::RobotNode node(runtime.bus(), runtime.loop(), runtime.heartbeat(), config);
  runtime.OnStop([&] { node.Shutdown(); });
  return runtime.Run();
}

}  // namespace

void RegisterRobot(CLI::App& root, int* exit_code) {
  auto args = std::make_shared<RobotArgs>();
  robot::RobotNodeConfig& c = args->config;
  args->watchdog_timeout_ms = c.watchdog_timeout.count();
  CLI::App* command = root.add_subcommand(
      "robot",
      "Run the avc-robot service: the UR5 (CB3) driver.\n"
      "State comes from RTDE (30004) at the controller's rate; motions are URScript programs on\n"
      "the secondary port (30002), checked against the safety envelope before anything is sent;\n"
      "power, brakes and protective stops go through the dashboard (29999).\n"
      "Every command but STOP and POWER_OFF must be signed with the cell's key (avc key).\n"
      "Real arm: avc robot --host 192.168.1.10   Simulated cell: avc robot --host 127.0.0.1");
  command->add_option("--host", c.host, "controller address")->capture_default_str();
  command->add_option("--rtde-port", c.rtde_port, "RTDE port")->capture_default_str();
  command->add_option("--secondary-port", c.secondary_port, "secondary (script) port")
      ->capture_default_str();
  command->add_option("--dashboard-port", c.dashboard_port, "dashboard port")
      ->capture_default_str();
  AddEnvelopeFlags(command, &args->envelope);
  command->add_option("--max-joint-speed", c.envelope.max_joint_speed_rad_s, "rad/s")
      ->capture_default_str();
  command->add_option("--max-linear-speed", c.envelope.max_linear_speed_m_s, "m/s")
      ->capture_default_str();
  command
      ->add_option("--watchdog-service", c.watchdog_service,
                   "service whose heartbeat guards motions (\"\" disables the watchdog)")
      ->capture_default_str();
  command
      ->add_option("--watchdog-timeout-ms", args->watchdog_timeout_ms,
                   "heartbeat silence after which a guarded motion is stopped")
      ->capture_default_str();
  AddDriverAuthFlags(command, &args->auth);
  AddBusFlags(command, &args->bus);
  SetGuardedRun(command, exit_code, [args] { return RunRobot(*args); });
}

}  // namespace avc::cli
