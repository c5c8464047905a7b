#include "drivers/robot/robot_options.h"

#include <stdexcept>
#include <string>

#include "core/kinematics/envelope_option_table.h"

namespace avc::robot {
namespace {

using Table = config::OptionTable<RobotNodeConfig>;

void AddConnection(Table& table) {
  table.Add("host", [](auto& o) -> auto& { return o.host; }, {"", "the controller's address"})
      .Add("rtde_port", [](auto& o) -> auto& { return o.rtde_port; }, {"", "RTDE port", 1, 65535})
      .Add("secondary_port", [](auto& o) -> auto& { return o.secondary_port; },
           {"", "secondary (script) port", 1, 65535})
      .Add("dashboard_port", [](auto& o) -> auto& { return o.dashboard_port; },
           {"", "dashboard port", 1, 65535})
      .Add("connect_timeout", [](auto& o) -> auto& { return o.connect_timeout; },
           {"ms", "a connection attempt gives up after this", 1, 600000})
      .Add("poll_period", [](auto& o) -> auto& { return o.poll_period; },
           {"ms", "state polling period (the CB3 controls at 8 ms)", 1, 10000})
      .Add("reconnect_min", [](auto& o) -> auto& { return o.reconnect_min; },
           {"ms", "first pause before reconnecting; doubles up to reconnect_max", 1, 600000})
      .Add("reconnect_max", [](auto& o) -> auto& { return o.reconnect_max; },
           {"ms", "longest pause between reconnection attempts", 1, 600000})
      .Add("state_rate_hz", [](auto& o) -> auto& { return o.state_rate_hz; },
           {"Hz", "ROBOT_STATE publication rate", 0.1, 1000});
}

void AddMotion(Table& table) {
  table
      .Add("default_joint_speed", [](auto& o) -> auto& { return o.default_joint_speed; },
           {"rad/s", "joint speed when a command gives 0", 0.001, 10})
      .Add("default_joint_acceleration",
           [](auto& o) -> auto& { return o.default_joint_acceleration; },
           {"rad/s^2", "joint acceleration when a command gives 0", 0.001, 100})
      .Add("default_linear_speed", [](auto& o) -> auto& { return o.default_linear_speed; },
           {"m/s", "tool speed when a command gives 0", 0.001, 10})
      .Add("default_linear_acceleration",
           [](auto& o) -> auto& { return o.default_linear_acceleration; },
           {"m/s^2", "tool acceleration when a command gives 0", 0.001, 100})
      .Add("stop_deceleration", [](auto& o) -> auto& { return o.stop_deceleration; },
           {"rad/s^2", "deceleration of every stop (STOP, watchdog, shutdown)", 0.1, 100})
      .Add("tolerance.joint_rad", [](auto& o) -> auto& { return o.tolerance.joint_rad; },
           {"rad", "a move is done with every joint this close to its target", 0, 1})
      .Add("tolerance.position_m", [](auto& o) -> auto& { return o.tolerance.position_m; },
           {"m", "... and the tool this close", 0, 1})
      .Add("tolerance.rotation_rad", [](auto& o) -> auto& { return o.tolerance.rotation_rad; },
           {"rad", "... and turned this close", 0, 1})
      .Add("tolerance.still_rad_s", [](auto& o) -> auto& { return o.tolerance.still_rad_s; },
           {"rad/s", "joints slower than this count as stopped", 0, 1})
      .Add("motion_timeout", [](auto& o) -> auto& { return o.motion_timeout; },
           {"ms", "a move not done after this fails", 1, 3600000})
      .Add("mode_change_timeout", [](auto& o) -> auto& { return o.mode_change_timeout; },
           {"ms", "power, brakes or unlock not reached after this fail", 1, 3600000})
      .Add("watchdog_service", [](auto& o) -> auto& { return o.watchdog_service; },
           {"", "the service whose heartbeat guards motions (\"\": no watchdog)"})
      .Add("watchdog_timeout", [](auto& o) -> auto& { return o.watchdog_timeout; },
           {"ms", "heartbeat silence after which a guarded motion is stopped", 1, 60000});
}

void AddEnvelope(Table& table) {
  kinematics::AddFixedEnvelopeOptions(
      table, "envelope", [](auto& o) -> auto& { return o.envelope; });
  table
      .Add("envelope.max_joint_speed",
           [](auto& o) -> auto& { return o.envelope.max_joint_speed_rad_s; },
           {"rad/s", "fastest joint speed a command may ask", 0.001, 10})
      .Add("envelope.max_joint_acceleration",
           [](auto& o) -> auto& { return o.envelope.max_joint_acceleration_rad_s2; },
           {"rad/s^2", "highest joint acceleration a command may ask", 0.001, 100})
      .Add("envelope.max_linear_speed",
           [](auto& o) -> auto& { return o.envelope.max_linear_speed_m_s; },
           {"m/s", "fastest tool speed a command may ask", 0.001, 10})
      .Add("envelope.max_linear_acceleration",
           [](auto& o) -> auto& { return o.envelope.max_linear_acceleration_m_s2; },
           {"m/s^2", "highest tool acceleration a command may ask", 0.001, 100})
      .Add("envelope.path_samples", [](auto& o) -> auto& { return o.envelope.path_samples; },
           {"", "points checked along each move's path", 2, 10000});
}

Table MakeTable() {
  // The key is not an option (it comes from the key file, avc key), so it is not checked here.
  Table table("robot", [](RobotNodeConfig o) {
    o.auth.allow_unsigned = true;
    return o.Validate();
  });
  AddConnection(table);
  AddMotion(table);
  AddEnvelope(table);
  return table;
}

}  // namespace

const config::OptionTable<RobotNodeConfig>& RobotOptionTable() {
  static const Table table = MakeTable();
  return table;
}

}  // namespace avc::robot
