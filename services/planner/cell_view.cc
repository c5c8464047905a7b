#include "services/planner/cell_view.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/cell/view_selection.h"

namespace avc::planner {
namespace {

double AzimuthAbout(const Eigen::Vector3d& point, const Eigen::Vector3d& centre) {
  return std::atan2(point.y() - centre.y(), point.x() - centre.x());
}

double ExteriorDistance(const Eigen::AlignedBox3d& box, const Eigen::Vector3d& point) {
  if (box.isEmpty()) return std::numeric_limits<double>::infinity();
  return box.exteriorDistance(point);
}

}  // namespace

std::optional<CellView> RealiseView(const cell::CellModel& cell, const Eigen::Vector3d& eye_world,
                                    const Eigen::Vector3d& target_world,
                                    const Eigen::AlignedBox3d& keep_out,
                                    const kinematics::JointVector& current,
                                    const ReachOptions& options) {
  if (!eye_world.allFinite() || !target_world.allFinite()) {
    throw std::invalid_argument("RealiseView: non-finite eye or target");
  }
  if ((eye_world - target_world).norm() < 1e-6) {
    throw std::invalid_argument("RealiseView: the eye is on the target");
  }
  if (eye_world.z() < options.table_clearance) return std::nullopt;
  if (ExteriorDistance(keep_out, eye_world) < options.plant_clearance) return std::nullopt;
  // The eye's azimuth about the axis in the table frame grows with the turntable angle: find
  // the angle that puts it at the arm's azimuth (plus an offset).
  const Eigen::Vector3d& centre = cell.turntable_centre_table;
  const double at_zero = AzimuthAbout(cell::TableFromWorld(cell, 0) * eye_world, centre);
  const double arm = cell::RobotAzimuth(cell);
  for (const double offset : options.azimuth_offsets) {
    const double angle = std::remainder(arm + offset - at_zero, 2 * M_PI);
    const Eigen::Isometry3d T_table_world = cell::TableFromWorld(cell, angle);
    const auto joints = cell::JointsLookingAt(cell, T_table_world * eye_world,
                                              T_table_world * target_world, current);
    if (!joints || !kinematics::JointPathAllowed(options.envelope, cell.dh, current, *joints)) {
      continue;
    }
    CellView view;
    view.turntable_angle = angle;
    view.joints = *joints;
    view.camera = cell::CameraAt(cell, *joints, angle);
    view.centre_world = view.camera.T_cam_world.inverse().translation();
    return view;
  }
  return std::nullopt;
}

}  // namespace avc::planner
