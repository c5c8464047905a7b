#include "core/kinematics/row_major_pose.h"

namespace avc::kinematics {

Eigen::Isometry3d IsometryFromRowMajor(const double* values) {
  Eigen::Matrix4d m;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) m(r, c) = values[4 * r + c];
  }
  Eigen::Isometry3d pose;
  pose.matrix() = m;
  return pose;
}

void RowMajorFromIsometry(const Eigen::Isometry3d& pose, double* values) {
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) values[4 * r + c] = pose.matrix()(r, c);
  }
}

}  // namespace avc::kinematics
