#pragma once

// Rigid transforms as the messages and files carry them: the 16 numbers of a 4x4, row by row.

#include <Eigen/Geometry>

namespace avc::kinematics {

Eigen::Isometry3d IsometryFromRowMajor(const double* values);
void RowMajorFromIsometry(const Eigen::Isometry3d& pose, double* values);

}  // namespace avc::kinematics
