#include "drivers/robot/plant_keep_out_command.h"

#include "core/kinematics/row_major_pose.h"

namespace avc::robot {

kinematics::PlantKeepOut PlantKeepOutOf(const avc::robot_command_t& command) {
  kinematics::PlantKeepOut keep_out;
  keep_out.T_base_table = kinematics::IsometryFromRowMajor(command.T_base_table);
  keep_out.z0_m = command.keep_out_z0;
  keep_out.slab_m = command.keep_out_slab;
  keep_out.radius_m = command.keep_out_radius;
  return keep_out;
}

}  // namespace avc::robot
