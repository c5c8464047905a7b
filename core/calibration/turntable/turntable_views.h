#pragma once

// Turntable calibration input and output. The board lies on the turntable and is observed from a
// frame that does not move with the table ("fixed": the camera with the arm still, or the robot
// base) at several commanded table angles. With the table turning right-handed by angle theta
// about the unit axis `a` through point `c` (CellTruth's convention), the board pose is
//   T_fixed_board(theta) = Rot(a, c, theta) * T_fixed_board(0).

#include <Eigen/Geometry>
#include <cmath>
#include <string>
#include <vector>

namespace avc::calibration {

struct TurntableView {
  double angle = 0;  // commanded table angle, radians
  Eigen::Isometry3d T_fixed_board = Eigen::Isometry3d::Identity();
};

struct TurntableAxis {
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  // unit; positive angles turn right-handed
  // The point on the axis in the plane of the circle the board origin travels on.
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
};

struct TurntableInputLimits {
  int min_views = 3;
  // The smallest arc holding every commanded angle must span at least this much.
  double min_span = 90 * M_PI / 180;
};

// The smallest arc (radians, [0, 2 pi)) on the circle that holds all angles.
double AngularSpan(const std::vector<double>& angles);

// Throws std::invalid_argument, naming `method`, for too few views, a non-finite angle or pose
// (naming its index), a pose whose rotation is not orthonormal, or angles spanning less than
// limits.min_span.
void ValidateTurntableViews(const std::vector<TurntableView>& views,
                            const TurntableInputLimits& limits, const std::string& method);

// T_fixed_table for an estimated axis: z along the axis, origin at the centre, x towards the
// board origin at angle 0 (`board_origin_at_zero`, fixed frame), projected off the axis.
Eigen::Isometry3d TableFrame(const TurntableAxis& axis,
                             const Eigen::Vector3d& board_origin_at_zero);

// Rotation by `angle` about the line through `centre` along unit `axis`.
Eigen::Isometry3d RotationAboutLine(const Eigen::Vector3d& axis, const Eigen::Vector3d& centre,
                                    double angle);

}  // namespace avc::calibration
