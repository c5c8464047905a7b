#include "services/planner/calibrated_cell.h"

#include <stdexcept>

namespace avc::planner {

cell::CellModel CellModelFromCalibration(const calibration::CellCalibration& calibration) {
  if (const std::string problem = calibration.Validate(); !problem.empty()) {
    throw std::invalid_argument("calibration not usable for planning: " + problem);
  }
  cell::CellModel cell;
  cell.dh = calibration.dh;
  cell.T_base_table = calibration.T_base_table;
  cell.turntable_axis_table = Eigen::Vector3d::UnitZ();
  cell.turntable_centre_table = Eigen::Vector3d::Zero();
  cell.T_flange_cam = calibration.T_flange_cam;
  cell.intrinsics = calibration.intrinsics;
  return cell;
}

}  // namespace avc::planner
