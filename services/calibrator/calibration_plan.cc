#include "services/calibrator/calibration_plan.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/cell/view_selection.h"

namespace avc::calibrator {
namespace {

constexpr double kDeg = std::numbers::pi / 180;

// Every corner of the board (at table angle `angle`) inside the nominal image with a margin of
// a tenth of the image.
bool SeesWholeBoard(const cell::CellModel& nominal, const calibration::ChessboardSpec& board,
                    const Eigen::Isometry3d& T_table_cam, double angle) {
  camera::Camera camera;
  camera.intrinsics = nominal.intrinsics;
  camera.T_cam_world =
      T_table_cam.inverse() * Eigen::Isometry3d(Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()));
  const double margin_x = 0.1 * nominal.intrinsics.width;
  const double margin_y = 0.1 * nominal.intrinsics.height;
  for (const Eigen::Vector3d& corner : calibration::ChessboardCorners(board)) {
    const auto pixel = camera.Project(board.T_world_board * corner);
    if (!pixel || pixel->x() < margin_x || pixel->y() < margin_y ||
        pixel->x() > nominal.intrinsics.width - margin_x ||
        pixel->y() > nominal.intrinsics.height - margin_y) {
      return false;
    }
  }
  return true;
}

Eigen::Isometry3d Rolled(const Eigen::Isometry3d& T_table_cam, double roll) {
  return T_table_cam * Eigen::Isometry3d(Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitZ()));
}

}  // namespace

CalibrationPlan PlanCalibration(const cell::CellModel& nominal,
                                const calibration::ChessboardSpec& board,
                                const kinematics::JointVector& start,
                                const CalibrationPlanOptions& options) {
  const Eigen::Vector3d target =
      board.T_world_board * Eigen::Vector3d(0.5 * (board.inner_cols - 1) * board.square_m,
                                            0.5 * (board.inner_rows - 1) * board.square_m, 0);
  const Eigen::Vector3d base = nominal.T_base_table.inverse().translation();
  const double robot_azimuth = cell::RobotAzimuth(nominal);
  CalibrationPlan plan;
  kinematics::JointVector current = start;
  // Candidates in a fixed order that varies elevation, azimuth, roll and distance together.
  const double elevations[] = {70, 50, 60, 40, 65, 45};
  const double azimuths[] = {0, 35, -35, 60, -60, 15, -15};
  const double rolls[] = {0, 30, -30, 15, -15};
  const double distances[] = {0.45, 0.55, 0.5, 0.6};
  for (int i = 0; i < 210 && static_cast<int>(plan.hand_eye.size()) < options.hand_eye_poses; ++i) {
    const double elevation = elevations[i % 6] * kDeg;
    const double azimuth = robot_azimuth + azimuths[i % 7] * kDeg;
    const double roll = rolls[i % 5] * kDeg;
    const double distance = distances[i % 4];
    const Eigen::Isometry3d T_table_cam =
        Rolled(cell::LookAtPose(cell::ViewpointOnSphere(target, distance, elevation, azimuth),
                                target, base),
               roll);
    if (!SeesWholeBoard(nominal, board, T_table_cam, 0)) continue;
    const auto q = cell::JointsForCameraPose(nominal, T_table_cam, current);
    if (!q || !kinematics::JointPathAllowed(options.envelope, nominal.dh, current, *q)) continue;
    plan.hand_eye.push_back(*q);
    current = *q;
  }
  if (static_cast<int>(plan.hand_eye.size()) < options.hand_eye_poses) {
    throw std::runtime_error(fmt::format(
        "only {} of {} hand-eye poses are reachable with the whole board in view; check the "
        "board size and where the table is",
        plan.hand_eye.size(), options.hand_eye_poses));
  }
  for (int k = 0; k < options.table_angles; ++k) {
    plan.table_angles.push_back(2 * std::numbers::pi * k / options.table_angles);
  }
  // The turntable pose: looking down at the table centre from as close as keeps the board in
  // view at every angle.
  for (const double distance : {0.55, 0.6, 0.65, 0.7, 0.8}) {
    for (const double elevation : {75.0, 70.0, 80.0, 65.0}) {
      const Eigen::Isometry3d T_table_cam =
          cell::LookAtPose(cell::ViewpointOnSphere(Eigen::Vector3d::Zero(), distance,
                                                   elevation * kDeg, robot_azimuth),
                           Eigen::Vector3d::Zero(), base);
      bool sees_all = true;
      for (const double angle : plan.table_angles) {
        sees_all = sees_all && SeesWholeBoard(nominal, board, T_table_cam, angle);
      }
      if (!sees_all) continue;
      const auto q = cell::JointsForCameraPose(nominal, T_table_cam, current);
      if (q && kinematics::JointPathAllowed(options.envelope, nominal.dh, current, *q)) {
        plan.turntable_pose = *q;
        return plan;
      }
    }
  }
  throw std::runtime_error(
      "no reachable pose keeps the whole board in view at every table angle; use a smaller "
      "board or fewer angles");
}

}  // namespace avc::calibrator
