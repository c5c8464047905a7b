#pragma once

// Whether a set of robot orientations can determine AX = ZB. The rotation part has a one-parameter
// family of solutions when every relative rotation R_j R_i^T turns about one axis, and is poorly
// conditioned when the rotations are small; both are refused before solving.

#include <Eigen/Core>
#include <numbers>
#include <string>
#include <vector>

namespace avc::calibration::hand_eye {

struct MotionDiversity {
  // Largest angle of any relative rotation R_j R_i^T (radians).
  double largest_rotation_rad = 0;
  // Spread of the relative rotations' axes: with S = sum over pairs of w w^T (w = angle * axis)
  // and its two largest eigenvalues l1 >= l2, 2 atan(sqrt(l2 / l1)). Two equally large motions
  // about axes phi apart give phi; motions about one axis give 0.
  double axis_spread_rad = 0;
};

// Over all pairs of `rotations` (each a rotation matrix).
MotionDiversity MeasureMotionDiversity(const std::vector<Eigen::Matrix3d>& rotations);

struct DiversityLimits {
  int min_poses = 3;
  double min_largest_rotation_rad = 5.0 * std::numbers::pi / 180;
  double min_axis_spread_rad = 5.0 * std::numbers::pi / 180;
};

// Empty when the poses suffice, else a sentence saying why not (too few poses, too little
// rotation, rotations about a single axis) with the measured figures.
std::string DegeneracyReason(const std::vector<Eigen::Matrix3d>& rotations,
                             const DiversityLimits& limits);

}  // namespace avc::calibration::hand_eye
