#pragma once

// avc-robot's options (connection, motion defaults, watchdog, safety envelope), declared once for
// --config, --set, the configuration it publishes and --help (core/config/option_table.h).

#include "core/config/option_table.h"
#include "drivers/robot/robot_node.h"

namespace avc::robot {

const config::OptionTable<RobotNodeConfig>& RobotOptionTable();

}  // namespace avc::robot
