#pragma once

// The plant keep-out a robot_command_t (KIND_SET_PLANT_KEEP_OUT) carries, as avc-robot reads it:
// shared by the node and the robot_command fuzz target, so both run the same conversion.

#include <avc/robot_command_t.hpp>

#include "core/kinematics/plant_keep_out.h"

namespace avc::robot {

// No slabs: an empty keep-out (clears it). Not validated: call Validate() on the result.
kinematics::PlantKeepOut PlantKeepOutOf(const avc::robot_command_t& command);

}  // namespace avc::robot
