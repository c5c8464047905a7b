#include "core/surface/plane_frame.h"

#include <Eigen/Geometry>

namespace avc::surface {

PlaneFrame MakePlaneFrame(const Eigen::Vector3d& origin, const Eigen::Vector3d& normal,
                          const Eigen::Vector3d& first_axis) {
  PlaneFrame frame;
  frame.origin = origin;
  frame.normal = normal.normalized();
  Eigen::Vector3d u = first_axis - first_axis.dot(frame.normal) * frame.normal;
  if (u.norm() < 1e-9) {
    // Any perpendicular: the axis least aligned with the normal, made orthogonal.
    Eigen::Index least = 0;
    frame.normal.cwiseAbs().minCoeff(&least);
    const Eigen::Vector3d axis = Eigen::Vector3d::Unit(least);
    u = axis - axis.dot(frame.normal) * frame.normal;
  }
  frame.u = u.normalized();
  frame.v = frame.normal.cross(frame.u);
  return frame;
}

}  // namespace avc::surface
