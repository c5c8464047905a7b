#pragma once

// An orthonormal frame on a regression plane: the 2-D coordinates cells are triangulated in
// (Phase 1) and stitched in (Phase 4), and where Phase 2 would grow a boundary.

#include <Eigen/Core>

namespace avc::surface {

struct PlaneFrame {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d u = Eigen::Vector3d::UnitX();  // in the plane
  Eigen::Vector3d v = Eigen::Vector3d::UnitY();  // in the plane, v = normal x u
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();

  Eigen::Vector2d Project(const Eigen::Vector3f& p) const {
    const Eigen::Vector3d d = p.cast<double>() - origin;
    return {d.dot(u), d.dot(v)};
  }
};

// A right-handed frame (u, v, normal) through origin with the given unit normal; u is along
// first_axis made perpendicular (or any perpendicular when first_axis is parallel to normal).
PlaneFrame MakePlaneFrame(const Eigen::Vector3d& origin, const Eigen::Vector3d& normal,
                          const Eigen::Vector3d& first_axis);

}  // namespace avc::surface
