// avc robot: the avc-robot service, the UR5 driver. Connects to the controller (RTDE 30004,
// secondary 30002, dashboard 29999), publishes ROBOT_STATE and executes ROBOT_COMMAND within a
// safety envelope. A lost controller is reconnected (heartbeat ERROR meanwhile), never a reason
// to exit; SIGTERM stops any motion and ends the process cleanly.

#include <memory>
#include <optional>
#include <vector>

#include "core/bus/service_runtime.h"
#include "drivers/robot/robot_node.h"
#include "drivers/robot/robot_options.h"
#include "tools/avc/auth_flags.h"
#include "tools/avc/bus_flags.h"
#include "tools/avc/commands.h"
#include "tools/avc/config_flags.h"
#include "tools/avc/envelope_flags.h"
#include "tools/avc/run_guarded.h"

namespace avc::cli {
namespace {

struct RobotArgs {
  EnvelopeFlags envelope;
  ConfigFlags config;
  AuthFlags auth;
  bus::BusFlags bus;
};

int RunRobot(const RobotArgs& args) {
  // The envelope flags come with the other shorthands: after the files, before --set.
  ConfigFlags flags = args.config;
  const std::vector<config::Assignment> envelope = EnvelopeSettings(args.envelope);
  flags.shorthands.insert(flags.shorthands.begin(), envelope.begin(), envelope.end());
  const auto& table = robot::RobotOptionTable();
  robot::RobotNodeConfig config = LoadOptions(table, flags);
  bus::ServiceRuntime runtime(config.service, args.bus);
  runtime.PublishConfig(table.ToToml(config));
  config.auth = DriverAuth(args.auth, runtime.bus().cell());
  robot::RobotNode node(runtime.bus(), runtime.loop(), runtime.heartbeat(), config);
  runtime.OnStop([&] { node.Shutdown(); });
  return runtime.Run();
}

}  // namespace

void RegisterRobot(CLI::App& root, int* exit_code) {
  auto args = std::make_shared<RobotArgs>();
  CLI::App* command = root.add_subcommand(
      "robot",
      "Run the avc-robot service: the UR5 (CB3) driver.\n"
      "State comes from RTDE (30004) at the controller's rate; motions are URScript programs on\n"
      "the secondary port (30002), checked against the safety envelope before anything is sent;\n"
      "power, brakes and protective stops go through the dashboard (29999).\n"
      "Every command but STOP and POWER_OFF must be signed with the cell's key (avc key).\n"
      "Real arm: avc robot --host 192.168.1.10   Simulated cell: avc robot --host 127.0.0.1");
  ConfigFlags* config = &args->config;
  AddShorthand(command, config, "--host", "host", "controller address");
  AddShorthand(command, config, "--rtde-port", "rtde_port", "RTDE port");
  AddShorthand(command, config, "--secondary-port", "secondary_port", "secondary (script) port");
  AddShorthand(command, config, "--dashboard-port", "dashboard_port", "dashboard port");
  AddEnvelopeFlags(command, &args->envelope);
  AddShorthand(command, config, "--max-joint-speed", "envelope.max_joint_speed", "rad/s");
  AddShorthand(command, config, "--max-linear-speed", "envelope.max_linear_speed", "m/s");
  AddShorthand(command, config, "--watchdog-service", "watchdog_service",
               "service whose heartbeat guards motions (\"\" disables the watchdog)");
  AddShorthand(command, config, "--watchdog-timeout-ms", "watchdog_timeout",
               "heartbeat silence after which a guarded motion is stopped");
  AddConfigFlags(command, config, robot::RobotOptionTable().Reference({}));
  AddDriverAuthFlags(command, &args->auth);
  AddBusFlags(command, &args->bus);
  SetGuardedRun(command, exit_code, [args] { return RunRobot(*args); });
}

}  // namespace avc::cli
